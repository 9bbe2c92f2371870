// The RTX's body as boxes in the frames of its chain, and the segment test against them.
#include <mrolr/arm/ArmBody.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::arm
{
namespace
{
constexpr double kColumnHalf_mm = 60, kLinkHalf_mm = 35, kStemHalf_mm = 20;
}

std::vector<BodyBox> rtxBody(const RtxOptions& rtx, const GraspFeasibilityOptions& grip,
                             const MarkerOptions& m)
{
	const double c = kColumnHalf_mm, l = kLinkHalf_mm, s = kStemHalf_mm;
	const double back = -grip.finger_length_mm / 2;
	const double half_open = grip.gripper_opening_max_mm / 2 + 10;
	const double plate = m.plateHalfMm();  // the code and its white quiet zone
	const Eigen::Vector3d& p = m.p_MinG_mm;
	return {
	    {0, {-c, -c, 0}, {c, c, rtx.d1_top_mm + 60}},                 // column
	    {1, {-c - 10, -c - 10, -50}, {c + 10, c + 10, 10}},           // carriage
	    {2, {-rtx.a2_mm, -l, -l}, {0, l, l}},                         // upper arm
	    {3, {-rtx.a3_mm, -l + 5, -l + 5}, {0, l - 5, l - 5}},         // forearm
	    {6, {-s, -s, -rtx.d6_mm}, {s, s, back - 10}},                 // wrist stem
	    {6, {-grip.finger_width_mm / 2 - 5, -half_open, back - 10},
	     {grip.finger_width_mm / 2 + 5, half_open, back}},            // palm
	    {6, {s, p.y() - 4, p.z() - 4}, {p.x() - 4, p.y() + 4, p.z() + 4}},  // marker stalk
	    {6, {p.x() - 4, p.y() - plate, p.z() - plate}, {p.x() - 2, p.y() + plate, p.z() + plate}},
	};
}

std::vector<PlacedBox> placeBody(const std::vector<BodyBox>& body, const RtxKinematics& kin,
                                 const RtxJoints& j, const Eigen::Isometry3d& T_AinRef_mm)
{
	const auto T0i = kin.linkFrames(j);
	std::vector<PlacedBox> out;
	for (const auto& b : body)
	{
		PlacedBox p;
		p.T_BoxInRef = T_AinRef_mm * T0i.at(static_cast<size_t>(b.frame)) *
		               Eigen::Translation3d((b.lo_mm + b.hi_mm) / 2);
		p.half_mm = (b.hi_mm - b.lo_mm) / 2;
		out.push_back(p);
	}
	return out;
}

bool segmentMeetsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const PlacedBox& box,
                     double margin_mm)
{
	const Eigen::Isometry3d inv = box.T_BoxInRef.inverse();
	const Eigen::Vector3d p = inv * a, d = inv.linear() * (b - a);
	double t0 = 0, t1 = 1;
	for (int i = 0; i < 3; ++i)
	{
		const double h = box.half_mm[i] + margin_mm;
		if (std::abs(d[i]) < 1e-12)
		{
			if (std::abs(p[i]) > h) return false;
			continue;
		}
		double ta = (-h - p[i]) / d[i], tb = (h - p[i]) / d[i];
		if (ta > tb) std::swap(ta, tb);
		t0 = std::max(t0, ta), t1 = std::min(t1, tb);
		if (t0 > t1) return false;
	}
	return true;
}

}  // namespace mrolr::arm
