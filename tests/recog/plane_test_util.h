#pragma once
/** Shared helpers of the support-plane tests (plane_hypotheses_test.cpp,
 * plane_recogniser_images_test.cpp): a tilted table, upright poses on it, line features. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/plane/SupportPlane.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace mrolr::recog::plane_test
{
/** A camera 35° down onto a table top through (0, -200, 650) mm (left camera frame L: x left,
 * y up, z forward). */
inline SupportPlane table()
{
	const double a = 35 * M_PI / 180;
	return SupportPlane::through({0, -200, 650}, {0, std::cos(a), -std::sin(a)});
}

/** The model upright on @p plane: its +z along the normal, its origin (base) at @p p_S, turned
 * by @p yaw about the normal. */
inline Eigen::Isometry3d upright(const SupportPlane& plane, const Eigen::Vector3d& p_S, double yaw)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(yaw, plane.n_S) *
	              Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), plane.n_S))
	                 .toRotationMatrix();
	T.translation() = p_S - plane.height_mm(p_S) * plane.n_S;
	return T;
}

/** Index of the model line that is horizontal at height @p z_mm and longest. */
inline size_t longestLineAt(const std::vector<Feature>& fs, double z_mm)
{
	size_t best = fs.size();
	for (size_t i = 0; i < fs.size(); ++i)
		if (fs[i].isLine() && std::abs(fs[i].u.z()) < 1e-6 && std::abs(fs[i].m.z() - z_mm) < 1e-6 &&
		    (best == fs.size() || fs[i].len_mm > fs[best].len_mm))
			best = i;
	return best;
}

/** The part [0, @p f] of a line (a fragment sharing its start). */
inline Feature fragment(const Feature& l, double f)
{
	Feature g = l;
	g.p2 = l.p1 + f * (l.p2 - l.p1);
	g.m = 0.5 * (g.p1 + g.p2);
	g.len_mm = f * l.len_mm;
	return g;
}

/** A line feature from @p a to @p b. */
inline Feature lineFeature(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	Feature f;
	f.p1 = a, f.p2 = b, f.m = 0.5 * (a + b);
	f.len_mm = (b - a).norm();
	f.u = (b - a) / f.len_mm;
	return f;
}
}  // namespace mrolr::recog::plane_test
