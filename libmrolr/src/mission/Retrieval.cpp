// Grasp planning, checking, reaching, visual verification and lifting (thesis 6.6–6.7, 7.2.2).
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/SolidSampling.h>
#include <mrolr/mission/Retrieval.h>
#include "RetrievalDetail.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace mrolr::mission
{
using detail::angleBetweenDeg;

namespace
{
Eigen::Isometry3d shifted(const Eigen::Isometry3d& T, const Eigen::Vector3d& d_mm_in_A)
{
	Eigen::Isometry3d out = T;
	out.translation() += d_mm_in_A;
	return out;
}

/** The pre-grasp pose: @p back_mm behind the grasp along the approach axis z_G. */
Eigen::Isometry3d preGrasp(const Eigen::Isometry3d& T_GinA, double back_mm)
{
	return T_GinA * Eigen::Translation3d(0, 0, -back_mm);
}

/** The highest point of @p model at @p T_OinA (mm, A's z): its segments' ends and its conics
 * sampled every 30°. */
double topInA(const model::WireFrame& model, const Eigen::Isometry3d& T_OinA)
{
	double top = -std::numeric_limits<double>::infinity();
	for (const auto& l : model.lines)
		top = std::max({top, (T_OinA * l.p1).z(), (T_OinA * l.p2).z()});
	for (const auto& c : model.conics)
		for (int k = 0; k < 12; ++k) top = std::max(top, (T_OinA * c.pointAt(k * M_PI / 6)).z());
	return top;
}

/** Joint distance for choosing among IK solutions (1 mm of column ~ 1 mrad). */
double jointDistance(const arm::RtxJoints& a, const arm::RtxJoints& b)
{
	double d = std::abs(a.d1_mm - b.d1_mm) / 1000.0;
	for (size_t i = 0; i < 6; ++i) d += std::abs(a.q_rad[i] - b.q_rad[i]);
	return d;
}

/** A step of a straight move whose joints jump further than this changed branch (elbow or
 * wrist flipped at a joint limit): the line cannot be followed (rad over kStraightStep_mm). */
constexpr double kMaxStepJump = 0.35;

std::string mm(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.1f mm", v);
	return buf;
}
}  // namespace

Retrieval::Retrieval(const MissionOptions& o, const model::WireFrame& target)
    : o_(o), target_(target), ik_(o.rtx), kin_(o.rtx), T_C0inA_(o.dock.T_C0inA)
{
}

double Retrieval::tableZinA(double top_height_m, const Eigen::Vector3d& p_OinC0_mm) const
{
	const double y_mm = 1000.0 * (top_height_m - o_.bisight.head_height_m);
	return (T_C0inA_ * Eigen::Vector3d(p_OinC0_mm.x(), y_mm, p_OinC0_mm.z())).z();
}

arm::GraspCheck Retrieval::check(const Eigen::Isometry3d& T_OinA, const Eigen::Isometry3d& T_GinA,
                                 double table_z_mm) const
{
	const auto pts = arm::sampleSolid(target_, T_OinA, o_.grasp.sample_step_mm);
	return arm::checkGrasp(T_GinA, pts, {}, table_z_mm, ik_, o_.grasp);
}

Eigen::Isometry3d Retrieval::graspInObject(double turn_deg) const
{
	return Eigen::AngleAxisd(turn_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
	       arm::graspInObject(target_.grasp);
}

bool Retrieval::planGrasp(RetrievalResult& r, double table_z_mm) const
{
	std::vector<double> turns{0};
	const double step = o_.retrieval.grasp_yaw_search_deg;
	for (int k = 1; step > 0 && k * step < 180 + 1e-9; ++k)
		turns.insert(turns.end(), {k * step, -k * step});
	for (double turn : turns)
	{
		const Eigen::Isometry3d T_GinA = r.T_OinA * graspInObject(turn);
		auto c = check(r.T_OinA, T_GinA, table_z_mm);
		std::optional<arm::RtxJoints> grasp;  // a solution reached straight from its pre-grasp
		for (const auto& sol : c.solutions)
			if (const auto pre = preGraspJoints(T_GinA, sol.joints);
			    !grasp && pre && straightPath(*pre, sol.joints))
				grasp = sol.joints;
		if (c.feasible() && !grasp)
			c.reasons.push_back(
			    "no IK solution for a pre-grasp pose from which the fingers come straight in");
		if (turn == 0) r.reasons = c.reasons, r.T_GinA = T_GinA;
		if (!c.feasible()) continue;
		r.T_GinA = T_GinA, r.grasp_turn_deg = turn, r.joints = *grasp;
		r.T_GinO = graspInObject(turn);
		r.reasons.clear();
		return true;
	}
	if (turns.size() > 1) r.reasons.push_back("no feasible grasp at any turn about the vertical");
	return false;
}

std::optional<arm::RtxJoints> Retrieval::preGraspJoints(const Eigen::Isometry3d& T_GinA,
                                                         const arm::RtxJoints& near) const
{
	if (auto j = solve(preGrasp(T_GinA, o_.retrieval.approach_mm), near)) return j;
	return solve(shifted(T_GinA, {0, 0, o_.retrieval.approach_mm}), near);
}

std::optional<arm::RtxJoints> Retrieval::solve(const Eigen::Isometry3d& T_GinA,
                                               const arm::RtxJoints& near) const
{
	const auto r = ik_.solve(T_GinA);
	if (r.solutions.empty()) return std::nullopt;
	return std::min_element(r.solutions.begin(), r.solutions.end(),
	                        [&](const arm::IkSolution& a, const arm::IkSolution& b)
	                        { return jointDistance(a.joints, near) < jointDistance(b.joints, near); })
	    ->joints;
}

void Retrieval::moveTo(hw::ArmDevice& arm, const arm::RtxJoints& j, Timeline& timeline) const
{
	arm.moveTo(j.toMmDeg());
	timeline.advance(o_.retrieval.arm_move_time_s);
}

std::optional<std::vector<arm::RtxJoints>> Retrieval::straightPath(const arm::RtxJoints& from,
                                                                   const arm::RtxJoints& to) const
{
	const Eigen::Isometry3d a = kin_.T06(from), b = kin_.T06(to);
	const double length = std::max((b.translation() - a.translation()).norm(),
	                               kStraightRadius_mm * angleBetweenDeg(a, b) * M_PI / 180.0);
	const int n = std::clamp(static_cast<int>(std::ceil(length / kStraightStep_mm)), 1, 200);
	const Eigen::Quaterniond qa(a.linear()), qb(b.linear());
	std::vector<arm::RtxJoints> path;
	arm::RtxJoints last = from;
	for (int k = 1; k <= n; ++k)
	{
		const double t = static_cast<double>(k) / n;
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.linear() = qa.slerp(t, qb).toRotationMatrix();
		T.translation() = (1 - t) * a.translation() + t * b.translation();
		const auto next = k == n ? std::optional(to) : solve(T, last);
		if (!next || jointDistance(*next, last) > kMaxStepJump) return std::nullopt;
		path.push_back(last = *next);
	}
	return path;
}

std::optional<std::vector<arm::RtxJoints>> Retrieval::crossing(const arm::RtxJoints& from,
                                                                const arm::RtxJoints& to) const
{
	const Eigen::Isometry3d T_from = kin_.T06(from), T_to = kin_.T06(to);
	const double z_from = T_from.translation().z(), z_to = T_to.translation().z();
	// level pre-grasps (both beside the object) are joined straight: the line stays as far out;
	// one above the object and one beside it are not (the line would cut through the object)
	if (std::abs(z_to - z_from) <= kLevel_mm && straightPath(from, to))
		return std::vector<arm::RtxJoints>{to};
	const double high = std::max(z_from, z_to) + o_.retrieval.approach_mm;
	const auto a = solve(shifted(T_from, {0, 0, high - z_from}), from);
	const auto b = a ? solve(shifted(T_to, {0, 0, high - z_to}), *a) : std::nullopt;
	if (a && b && straightPath(from, *a) && straightPath(*a, *b) && straightPath(*b, to))
		return std::vector<arm::RtxJoints>{*a, *b, to};
	return std::nullopt;
}

void Retrieval::moveStraight(hw::ArmDevice& arm, const arm::RtxJoints& j, Timeline& timeline) const
{
	const auto path = straightPath(arm::RtxJoints::fromMmDeg(arm.joints()), j);
	for (const auto& step : path ? *path : std::vector<arm::RtxJoints>{j})
		arm.moveTo(step.toMmDeg());
	timeline.advance(o_.retrieval.arm_move_time_s);
}

bool Retrieval::feasibleAt(const Eigen::Isometry3d& T_OinC0_mm, double table_top_height_m,
                           std::vector<std::string>* reasons) const
{
	RetrievalResult r;
	r.T_OinA = arm::objectInArm(T_C0inA_, T_OinC0_mm);
	const bool ok = planGrasp(r, tableZinA(table_top_height_m, T_OinC0_mm.translation()));
	if (reasons) *reasons = r.reasons;
	return ok;
}

Eigen::Isometry3d Retrieval::graspAt(const Eigen::Isometry3d& T_OinC0_mm, double turn_deg) const
{
	return arm::objectInArm(T_C0inA_, T_OinC0_mm) * graspInObject(turn_deg);
}

RetrievalResult Retrieval::run(const Sighting& first, double table_top_height_m,
                               hw::ArmDevice& arm, const Reobserve& reobserve,
                               Timeline& timeline) const
{
	RetrievalResult r;
	r.T_OinC0_first_mm = first.T_OinC0_mm;
	r.T_OinC0_first_mm.translation().x() += o_.retrieval.inject_pose_error_mm;
	if (o_.retrieval.inject_pose_error_mm != 0)
		timeline.note("injected pose error " + mm(o_.retrieval.inject_pose_error_mm) +
		              " along C0's x");
	{
		ComputeTimer t(timeline);
		r.T_OinA = arm::objectInArm(T_C0inA_, r.T_OinC0_first_mm);
		r.feasible = planGrasp(r, tableZinA(table_top_height_m, r.T_OinC0_first_mm.translation()));
	}
	if (!r.feasible) return r;
	timeline.note("grasp planned (turned " + std::to_string(r.grasp_turn_deg) + " deg)");
	judgeAmbiguity(r, first, timeline);
	r.attempted = true;
	try
	{
		if (!reachAndVerify(r, arm, reobserve, timeline)) return r;
		closeAndLift(r, arm, timeline);
	}
	catch (const hw::ArmBlocked& e)
	{  // the arm stands where it stalled; the mission goes on without the object
		r.retrieved = false;
		r.reasons.push_back(std::string("the arm was blocked: ") + e.what());
		timeline.note(r.reasons.back());
	}
	return r;
}

void Retrieval::closeAndLift(RetrievalResult& r, hw::ArmDevice& arm, Timeline& timeline) const
{
	arm.setGripper(true);
	r.width_closed_mm = arm.gripperWidthMm();
	timeline.note("gripper closed, jaws " + mm(r.width_closed_mm) + " apart");
	if (r.width_closed_mm < o_.retrieval.min_held_width_mm)
	{
		r.reasons.push_back("the gripper closed on nothing (jaws " + mm(r.width_closed_mm) +
		                    " apart)");
		return;
	}
	if (const auto lift = solve(shifted(r.T_GinA, {0, 0, o_.retrieval.lift_mm}), r.joints))
		moveStraight(arm, *lift, timeline);
	else
		r.reasons.push_back("no IK solution for the lift pose");
	r.width_lifted_mm = arm.gripperWidthMm();
	r.retrieved = r.width_lifted_mm >= o_.retrieval.min_held_width_mm;
	if (!r.retrieved)
		r.reasons.push_back("the object slipped out during the lift (jaws " +
		                    mm(r.width_lifted_mm) + " apart)");
}

double Retrieval::swingColumnMm(const RetrievalResult& r, const arm::RtxJoints& above) const
{
	// the column and the links move the wrist centre level; the hand reaches d6 from it
	const Eigen::Isometry3d T = kin_.T06(above);
	const double wrist_z = T.translation().z() - o_.rtx.d6_mm * T.linear()(2, 2);
	const double needed = topInA(target_, r.T_OinA) + kSwingClearance_mm + o_.rtx.d6_mm - wrist_z;
	return above.d1_mm + std::max(0.0, needed);
}

arm::RtxJoints Retrieval::viewingJoints(const RetrievalResult& r, const arm::RtxJoints& pre) const
{
	if (!self_) return pre;
	const Eigen::Vector3d p_inC0_m = r.T_OinC0_first_mm * Eigen::Vector3d(0, 0, 30) / 1000.0;
	const double step = std::max(20.0, o_.retrieval.approach_mm);
	for (double up = 0; pre.d1_mm + up <= o_.rtx.d1_top_mm; up += step)
	{
		arm::RtxJoints j = pre;
		j.d1_mm += up;  // the column up: the hand rises straight above the pre-grasp
		if (!self_->isSelfAt(j.toMmDeg(), p_inC0_m)) return j;
	}
	return pre;
}

bool Retrieval::reachAndVerify(RetrievalResult& r, hw::ArmDevice& arm, const Reobserve& reobserve,
                               Timeline& timeline) const
{
	arm.setGripper(false);
	const auto pre = preGraspJoints(r.T_GinA, r.joints);
	if (!pre)
	{
		r.reasons.push_back("no IK solution for the pre-grasp pose");
		return false;
	}
	// come down onto the pre-grasp from above it (or onto the pre-grasp itself when the pose above
	// it has no solution): the column up first, the swing at a height where the hand clears the
	// object however the wrist turns on the way, then straight down the column
	const auto above = solve(shifted(preGrasp(r.T_GinA, o_.retrieval.approach_mm),
	                                 {0, 0, o_.retrieval.approach_mm}),
	                         *pre);
	const arm::RtxJoints& onto = above ? *above : *pre;
	const arm::RtxJoints now = arm::RtxJoints::fromMmDeg(arm.joints());
	arm::RtxJoints high = onto;
	high.d1_mm = std::min(std::max({swingColumnMm(r, onto), now.d1_mm, onto.d1_mm}),
	                      o_.rtx.d1_top_mm);
	arm::RtxJoints up = now;
	up.d1_mm = high.d1_mm;
	if (up.d1_mm > now.d1_mm) moveTo(arm, up, timeline);
	moveTo(arm, high, timeline);
	moveStraight(arm, onto, timeline);
	if (!o_.retrieval.visual_verification) moveStraight(arm, *pre, timeline);
	if (o_.retrieval.visual_verification)
	{
		// the head looks from where the arm leaves the object in view, then the arm comes down
		const auto view = viewingJoints(r, *pre);
		if (view.d1_mm != pre->d1_mm)
			timeline.note("verification view with the hand " + mm(view.d1_mm - pre->d1_mm) +
			              " above the pre-grasp, the arm clear of the object");
		moveStraight(arm, view, timeline);
		const auto seen = reobserve(r.T_OinC0_first_mm);
		if (view.d1_mm != pre->d1_mm) moveStraight(arm, *pre, timeline);
		if (seen)
			correct(r, seen->T_OinC0_mm, timeline);
		else
			timeline.note("verification: the object was not recognised again; first grasp kept");
		lookedAgain(r, seen, timeline);
	}
	// a corrected grasp is approached along its own axis, from its own pre-grasp
	if (r.correction_applied)
		for (const auto& j : r.correction_route) moveStraight(arm, j, timeline);
	moveStraight(arm, r.joints, timeline);
	timeline.note("at grasp pose (correction " + mm(r.correction_mm) +
	              (r.correction_applied ? ", applied)" : ", not applied)"));
	return true;
}

double Retrieval::nearestTurn(const RetrievalResult& r, const Eigen::Isometry3d& T_OinA) const
{
	const double step = o_.retrieval.grasp_yaw_search_deg;
	double best_turn = r.grasp_turn_deg, best = 1e9;
	for (int k = -3; k <= 3; ++k)
	{
		if (step <= 0 && k != 0) continue;
		const double turn = r.grasp_turn_deg + k * step;
		const double d = angleBetweenDeg(T_OinA * graspInObject(turn), r.T_GinA);
		if (d < best - 1e-6) best = d, best_turn = turn;
	}
	return best_turn;
}

void Retrieval::correct(RetrievalResult& r, const Eigen::Isometry3d& T_OinC0_mm,
                        Timeline& timeline) const
{
	ComputeTimer t(timeline);
	r.verified = true;
	r.T_OinC0_verified_mm = T_OinC0_mm;
	const Eigen::Isometry3d T_OinA = arm::objectInArm(T_C0inA_, T_OinC0_mm);
	const double turn = nearestTurn(r, T_OinA);
	const Eigen::Isometry3d T_GinA = T_OinA * graspInObject(turn);
	r.correction_mm = (T_GinA.translation() - r.T_GinA.translation()).norm();
	r.correction_deg = angleBetweenDeg(T_GinA, r.T_GinA);
	if (r.correction_mm > o_.retrieval.max_grasp_correction_mm)
	{
		r.correction_refused = true;
		r.reasons.push_back("verification correction " + mm(r.correction_mm) +
		                    " refused (above max_grasp_correction_mm = " +
		                    mm(o_.retrieval.max_grasp_correction_mm) + "); first grasp kept");
		timeline.note(r.reasons.back());
		return;
	}
	const auto j = solve(T_GinA, r.joints);
	if (!j)
	{
		r.reasons.push_back("no IK solution for the verified grasp; first grasp kept");
		return;
	}
	const auto pre = preGraspJoints(T_GinA, *j);
	if (!pre || !straightPath(*pre, *j))
	{
		r.reasons.push_back("the verified grasp cannot be approached straight from its pre-grasp "
		                    "on one arm branch; first grasp kept");
		timeline.note(r.reasons.back());
		return;
	}
	const auto first_pre = preGraspJoints(r.T_GinA, r.joints);
	const auto route = first_pre ? crossing(*first_pre, *pre) : std::nullopt;
	if (!route)
	{
		r.reasons.push_back("the verified pre-grasp cannot be reached from the first one on one "
		                    "arm branch, nor over it; first grasp kept");
		timeline.note(r.reasons.back());
		return;
	}
	r.correction_route = *route;
	if (route->size() > 1)
		timeline.note("the verified pre-grasp is not reached straight from the first: over it "
		              "(up, across, down)");
	r.T_GinA = T_GinA, r.joints = *j, r.grasp_turn_deg = turn, r.correction_applied = true;
	r.T_GinO = graspInObject(turn);
}

}  // namespace mrolr::mission
