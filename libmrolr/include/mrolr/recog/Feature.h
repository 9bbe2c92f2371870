#pragma once
/** A wire-frame element as the matcher sees it (thesis 6.3, paper section 3): lines as the
 * quadruple (l1, l2, e, m) and conics as (centre, normal, radii, arc length). Every feature has a
 * signed direction `u` (line direction l1→l2 or conic normal); scene features are tried in both
 * signs because stereo fixes neither an endpoint order nor a normal sign. Millimetres. */

#include <mrolr/model/WireFrame.h>

#include <Eigen/Geometry>

#include <vector>

namespace mrolr::recog
{
enum class FeatureKind
{
	Line,
	Conic
};

struct Feature
{
	FeatureKind kind = FeatureKind::Line;
	int id = 0;                                    ///< the id in the wire-frame
	Eigen::Vector3d u = Eigen::Vector3d::UnitX();  ///< unit line direction or conic normal
	Eigen::Vector3d m = Eigen::Vector3d::Zero();   ///< line midpoint or conic centre (mm)
	Eigen::Vector3d p1 = Eigen::Vector3d::Zero();  ///< line start (mm); conic: centre
	Eigen::Vector3d p2 = Eigen::Vector3d::Zero();  ///< line end (mm); conic: centre
	double len_mm = 0;                             ///< line length or conic arc length (mm)
	double a_mm = 0;                               ///< conic semi-major axis (mm); 0 for lines
	double b_mm = 0;                               ///< conic semi-minor axis (mm); 0 for lines

	bool isLine() const { return kind == FeatureKind::Line; }
	/** The same feature with u negated (a line's endpoints swapped). */
	Feature flipped() const;
	/** The feature moved by the rigid transform @p T (model frame → scene frame). */
	Feature transformed(const Eigen::Isometry3d& T) const;
};

/** Lines then conics of @p wf; degenerate elements (zero length, zero radius, non-finite values)
 * are rejected with std::invalid_argument naming the element id. */
std::vector<Feature> featuresOf(const model::WireFrame& wf);

}  // namespace mrolr::recog
