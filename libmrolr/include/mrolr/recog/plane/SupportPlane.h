#pragma once
/** The plane the objects stand on (the table top), in the scene frame S (for the head's scenes the
 * left camera frame L, mm). Objects stand upright on it: their model frame's z = 0 (the base)
 * lies in it and their +z is its normal. Recognizer::recognize uses it to make pose hypotheses
 * from single scene features (PlaneHypotheses.h). */

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>

namespace mrolr::recog
{
struct SupportPlane
{
	Eigen::Vector3d n_S = Eigen::Vector3d::UnitY();  ///< unit normal, pointing up (scene frame)
	double d_mm = 0;  ///< offset: a point x of the scene frame is n_S·x + d_mm above the plane

	/** Signed height (mm) of @p p_S above the plane. */
	double height_mm(const Eigen::Vector3d& p_S) const { return n_S.dot(p_S) + d_mm; }

	/** The plane through @p p_S (mm) with the upward normal @p up_S (normalised here). Throws
	 * std::invalid_argument for a zero or non-finite normal or a non-finite point. */
	static SupportPlane through(const Eigen::Vector3d& p_S, const Eigen::Vector3d& up_S)
	{
		if (!up_S.allFinite() || up_S.norm() < 1e-12 || !p_S.allFinite())
			throw std::invalid_argument("support plane: the normal must be finite and non-zero");
		SupportPlane s;
		s.n_S = up_S.normalized();
		s.d_mm = -s.n_S.dot(p_S);
		return s;
	}
	/** The plane n·x + d = 0 from a (not necessarily unit) normal @p n_S and offset @p d_mm given
	 * for that normal; both are scaled so that the normal is unit. Throws as through(). */
	static SupportPlane fromCoefficients(const Eigen::Vector3d& n_S, double d_mm)
	{
		if (!n_S.allFinite() || n_S.norm() < 1e-12 || !std::isfinite(d_mm))
			throw std::invalid_argument(
			    "support plane: the normal must be finite and non-zero, the offset finite");
		SupportPlane s;
		const double k = n_S.norm();
		s.n_S = n_S / k;
		s.d_mm = d_mm / k;
		return s;
	}
};

}  // namespace mrolr::recog
