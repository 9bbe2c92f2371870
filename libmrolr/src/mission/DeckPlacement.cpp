// Planning the arm's motion that puts the retrieved object down on the robot's deck.
#include <mrolr/arm/BodyCollision.h>
#include <mrolr/arm/SolidSampling.h>
#include <mrolr/mission/DeckPlacement.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace mrolr::mission
{
namespace
{
constexpr double kSlabHalf_mm = 50;       ///< the deck's slab below its top face
constexpr double kSwingRadius_mm = 700;   ///< the farthest arm point from a joint axis
constexpr double kPointSpacing_mm = 10;   ///< spacing of the held object's tested points
constexpr double kDeckEdge_mm = 10;       ///< an object set down stays this far inside the deck
constexpr double kFingerThickness_mm = 8; ///< each finger plate across the jaws
constexpr double kRaiseStep_mm = 5;       ///< the release pose raised in these steps…
constexpr double kMaxRaise_mm = 60;       ///< …at most this far above drop_mm

std::vector<arm::BodyBox> bodyWithFingers(const MissionOptions& o)
{
	auto body = arm::rtxBody(o.rtx, o.grasp, o.marker);
	body.push_back(arm::fingerBox(o.grasp, kFingerThickness_mm));
	return body;
}

arm::PlacedBox box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half)
{
	arm::PlacedBox b;
	b.T_BoxInRef.translation() = centre;
	b.half_mm = half;
	return b;
}

bool inside(const Eigen::Isometry3d& T_RefInBox, const Eigen::Vector3d& half,
            const Eigen::Vector3d& p, double margin_mm)
{
	const Eigen::Vector3d q = T_RefInBox * p;
	return std::abs(q.x()) <= half.x() + margin_mm && std::abs(q.y()) <= half.y() + margin_mm &&
	       std::abs(q.z()) <= half.z() + margin_mm;
}

arm::RtxJoints atHeight(arm::RtxJoints j, double d1_mm)
{
	j.d1_mm = d1_mm;
	return j;
}

/** Tested poses of a straight joint-space move: its longest travel over @p step_mm. */
int movePoses(const arm::RtxJoints& a, const arm::RtxJoints& b, double step_mm)
{
	double q = 0;
	for (int i = 1; i <= 6; ++i) q = std::max(q, std::abs(b.q(i) - a.q(i)));
	const double travel = std::max(std::abs(b.d1_mm - a.d1_mm), q * kSwingRadius_mm);
	return std::clamp(static_cast<int>(std::ceil(travel / step_mm)), 1, 2000);
}

arm::RtxJoints lerp(const arm::RtxJoints& a, const arm::RtxJoints& b, double t)
{
	arm::RtxJoints j = a;
	j.d1_mm = a.d1_mm + t * (b.d1_mm - a.d1_mm);
	for (size_t i = 0; i < 6; ++i) j.q_rad[i] = a.q_rad[i] + t * (b.q_rad[i] - a.q_rad[i]);
	return j;
}
}  // namespace

DeckPlacement::DeckPlacement(const MissionOptions& o, const model::WireFrame& target,
                             const Eigen::Isometry3d& T_C0inA_mm)
    : o_(o),
      kin_(o.rtx),
      ik_(o.rtx),
      body_(bodyWithFingers(o)),
      self_pairs_(arm::selfCollisionPairs(body_)),
      T_C0inA_(T_C0inA_mm),
      T_AinC0_(T_C0inA_mm.inverse())
{
	const auto& b = o.labmate;
	const double head_mm = 1000.0 * o.bisight.head_height_m;
	deck_top_y_mm_ = 1000.0 * b.deck_height_m - head_mm;
	deck_ = box({0, deck_top_y_mm_ - kSlabHalf_mm, 0},
	            {500.0 * b.footprint_width_m, kSlabHalf_mm, 500.0 * b.footprint_length_m});
	const double mast_top_y = 1000.0 * b.mast_top_height_m - head_mm;
	mast_ = box({0, (deck_top_y_mm_ + mast_top_y) / 2, 0},
	            {1000.0 * b.mast_half_width_m, (mast_top_y - deck_top_y_mm_) / 2,
	             1000.0 * b.mast_half_width_m});
	points_O_ = arm::sampleSolid(target, Eigen::Isometry3d::Identity(), kPointSpacing_mm);
	for (const auto& p : points_O_)
	{
		footprint_radius_mm_ = std::max(footprint_radius_mm_, p.head<2>().norm());
		bottom_mm_ = std::min(bottom_mm_, p.z());
	}
}

Eigen::Isometry3d DeckPlacement::T_OinC0At(const Spot& s) const
{
	// upright: O's z along C0's y (up), O's x turned from C0's z towards C0's x by yaw
	Eigen::Matrix3d R0;
	R0.col(0) = Eigen::Vector3d::UnitZ(), R0.col(1) = Eigen::Vector3d::UnitX(),
	R0.col(2) = Eigen::Vector3d::UnitY();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(s.yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()) * R0;
	T.translation() = s.p_inC0_mm - Eigen::Vector3d(0, bottom_mm_, 0);  // the bottom on the spot
	return T;
}

std::vector<DeckPlacement::Spot> DeckPlacement::spots() const
{
	const auto& p = o_.place;
	const double hx = deck_.half_mm.x() - footprint_radius_mm_ - kDeckEdge_mm;
	const double hz = deck_.half_mm.z() - footprint_radius_mm_ - kDeckEdge_mm;
	std::vector<Spot> out;
	const double y = deck_top_y_mm_ + p.drop_mm;
	for (double z = -hz; z <= hz + 1e-9; z += p.grid_step_mm)
		for (double x = -hx; x <= hx + 1e-9; x += p.grid_step_mm)
			for (double yaw = 0; yaw < 360 - 1e-9; yaw += p.yaw_step_deg)
				out.push_back({{x, y, z}, yaw});
	// rearmost first (out of the head's forward view), then nearest the arm's column
	const Eigen::Vector3d column = T_AinC0_.translation();
	std::stable_sort(out.begin(), out.end(),
	                 [&](const Spot& a, const Spot& b)
	                 {
		                 if (std::abs(a.p_inC0_mm.z() - b.p_inC0_mm.z()) > 1e-6)
			                 return a.p_inC0_mm.z() < b.p_inC0_mm.z();
		                 return std::abs(a.p_inC0_mm.x() - column.x()) <
		                        std::abs(b.p_inC0_mm.x() - column.x());
	                 });
	return out;
}

std::string DeckPlacement::contactAt(const arm::RtxJoints& j,
                                     const std::optional<Eigen::Isometry3d>& T_GinO_mm,
                                     double object_floor_mm) const
{
	const auto placed = arm::placeBody(body_, kin_, j, T_AinC0_);
	const double m = o_.place.margin_mm;
	for (size_t i = 0; i < placed.size(); ++i)
	{
		if (body_[i].frame <= 1) continue;  // the column and its carriage stand on the deck
		if (arm::boxesOverlap(placed[i], deck_, m)) return "the " + arm::bodyBoxName(i) + " meets the deck";
		if (arm::boxesOverlap(placed[i], mast_, m)) return "the " + arm::bodyBoxName(i) + " meets the head's mast";
	}
	if (const auto c = arm::firstSelfContact(placed, self_pairs_, o_.place.self_margin_mm))
		return "the " + arm::bodyBoxName(c->first) + " meets the " + arm::bodyBoxName(c->second);
	if (!T_GinO_mm) return "";
	const Eigen::Isometry3d T_OinC0 = T_AinC0_ * kin_.T06(j) * T_GinO_mm->inverse();
	std::vector<Eigen::Isometry3d> into;  // C0 → each arm box but the hand's own
	for (size_t i = 0; i < placed.size(); ++i)
		into.push_back(body_[i].frame == 6 ? Eigen::Isometry3d::Identity()
		                                   : placed[i].T_BoxInRef.inverse());
	const Eigen::Isometry3d into_mast = mast_.T_BoxInRef.inverse();
	for (const auto& p_O : points_O_)
	{
		const Eigen::Vector3d p = T_OinC0 * p_O;
		if (p.y() < deck_top_y_mm_ + object_floor_mm && std::abs(p.x()) <= deck_.half_mm.x() &&
		    std::abs(p.z()) <= deck_.half_mm.z())
			return "the object meets the deck";
		if (inside(into_mast, mast_.half_mm, p, m)) return "the object meets the head's mast";
		for (size_t i = 0; i < placed.size(); ++i)
			if (body_[i].frame != 6 && inside(into[i], placed[i].half_mm, p, o_.place.self_margin_mm))
				return "the object meets the " + arm::bodyBoxName(i);
	}
	return "";
}

std::string DeckPlacement::contactAlong(const arm::RtxJoints& a, const arm::RtxJoints& b,
                                        const std::optional<Eigen::Isometry3d>& T_GinO_mm,
                                        double object_floor_mm, int& tested) const
{
	const int n = movePoses(a, b, o_.place.check_step_mm);
	for (int k = 0; k <= n; ++k)
	{
		++tested;
		const std::string c = contactAt(lerp(a, b, static_cast<double>(k) / n), T_GinO_mm, object_floor_mm);
		if (!c.empty()) return c;
	}
	return "";
}

std::string DeckPlacement::motionThrough(const arm::RtxJoints& lifted, const arm::RtxJoints& down,
                                         const arm::RtxJoints& parked,
                                         const Eigen::Isometry3d& T_GinO_mm, PlacePlan& plan) const
{
	const double travel = std::max(lifted.d1_mm, parked.d1_mm);
	const std::vector<arm::RtxJoints> carry{atHeight(lifted, travel), atHeight(down, travel), down};
	std::vector<arm::RtxJoints> leave{atHeight(down, travel), atHeight(parked, travel)};
	if (parked.d1_mm != travel) leave.push_back(parked);
	const double floor = o_.place.drop_mm / 2;
	arm::RtxJoints from = lifted;
	for (const auto& j : carry)
	{
		const auto c = contactAlong(from, j, T_GinO_mm, floor, plan.tested_poses);
		if (!c.empty()) return c + " while carrying the object";
		from = j;
	}
	for (const auto& j : leave)
	{
		const auto c = contactAlong(from, j, std::nullopt, 0, plan.tested_poses);
		if (!c.empty()) return c + " while leaving the object";
		from = j;
	}
	plan.carry = carry, plan.leave = leave;
	return "";
}

PlacePlan DeckPlacement::plan(const arm::RtxJoints& lifted, const Eigen::Isometry3d& T_GinO_mm,
                              const arm::RtxJoints& parked) const
{
	const auto t0 = std::chrono::steady_clock::now();
	PlacePlan plan;
	std::string nearest;  // the first candidate's reason, the most telling
	for (const auto& s : spots())
	{
		++plan.candidates;
		const Eigen::Isometry3d T_OinC0 = T_OinC0At(s);
		const auto ik = ik_.solve(T_C0inA_ * T_OinC0 * T_GinO_mm);
		if (ik.solutions.empty())
		{
			if (nearest.empty()) nearest = "no IK solution: " + ik.reason();
			continue;
		}
		++plan.solved;
		for (const auto& sol : ik.solutions)
		{
			// with a side grasp the links stand at the grasp's height: the jaws open higher up,
			// where the arm clears the deck (the object then drops a little further)
			std::string why;
			arm::RtxJoints down = sol.joints;
			for (double raise = 0; raise <= kMaxRaise_mm + 1e-9; raise += kRaiseStep_mm)
			{
				down = atHeight(sol.joints, sol.joints.d1_mm + raise);
				++plan.tested_poses;
				why = contactAt(down, T_GinO_mm, o_.place.drop_mm / 2);
				if (why.empty()) break;
			}
			if (why.empty()) why = motionThrough(lifted, down, parked, T_GinO_mm, plan);
			if (!why.empty())
			{
				if (nearest.empty() || nearest.rfind("no IK", 0) == 0) nearest = why;
				continue;
			}
			plan.found = true;
			plan.p_spotInC0_mm = T_OinC0.translation();
			plan.p_spotInC0_mm.y() = deck_top_y_mm_ - bottom_mm_;
			plan.yaw_deg = s.yaw_deg;
			plan.drop_mm = o_.place.drop_mm + (down.d1_mm - sol.joints.d1_mm);
			break;
		}
		if (plan.found) break;
	}
	if (!plan.found)
		plan.reason = "none of " + std::to_string(plan.candidates) +
		              " spots on the deck is reached by a free motion (" +
		              std::to_string(plan.solved) + " with an IK solution; first: " +
		              (nearest.empty() ? std::string("the object does not fit on the deck") : nearest) +
		              ")";
	plan.compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return plan;
}

}  // namespace mrolr::mission
