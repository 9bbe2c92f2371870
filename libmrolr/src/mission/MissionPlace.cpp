// The mission's last arm motion: the held object put down on the robot's deck, the arm parked.
#include "MissionImpl.h"

#include <cstdio>

namespace mrolr::mission
{
namespace
{
std::string spotText(const PlacePlan& p)
{
	char buf[160];
	std::snprintf(buf, sizeof buf, "(x %.0f, z %.0f) mm in C0, turned %.0f deg, let go %.0f mm above it",
	              p.p_spotInC0_mm.x(), p.p_spotInC0_mm.z(), p.yaw_deg, p.drop_mm);
	return buf;
}
}  // namespace

void Mission::Impl::placeOnBoard(const Eigen::Isometry3d& T_C0inA_mm)
{
	r.timeline.beginStage("place");
	auto& p = r.place;
	{
		ComputeTimer timer(r.timeline);
		const DeckPlacement deck(o, target, T_C0inA_mm);
		p.plan = deck.plan(arm::RtxJoints::fromMmDeg(dev.arm->joints()), r.retrieval.T_GinO,
		                   arm::RtxJoints::fromMmDeg(parked));
	}
	if (!p.plan.found)
	{
		p.reason = p.plan.reason;
		r.timeline.note("not put on board (" + p.reason + "): the gripper keeps the object");
		return;
	}
	r.timeline.note("putting the object on the deck at " + spotText(p.plan));
	p.attempted = true;
	auto move = [&](const arm::RtxJoints& j)
	{
		dev.arm->moveTo(j.toMmDeg());
		r.timeline.advance(o.retrieval.arm_move_time_s);
	};
	try
	{
		for (const auto& j : p.plan.carry) move(j);
		p.width_before_mm = dev.arm->gripperWidthMm();
		if (p.width_before_mm < o.retrieval.min_held_width_mm)
		{
			p.reason = "the object was lost on the way to the deck (jaws " +
			           std::to_string(p.width_before_mm) + " mm apart)";
			r.retrieved = false;
			r.failure = p.reason;
		}
		dev.arm->setGripper(false);
		p.placed = r.retrieved;
		for (const auto& j : p.plan.leave) move(j);
		r.timeline.note(p.placed ? "object put down on the deck, the arm parked" : p.reason);
	}
	catch (const hw::ArmBlocked& e)
	{
		p.reason = std::string("the arm was blocked: ") + e.what();
		r.timeline.note("putting the object on board: " + p.reason);
	}
}

}  // namespace mrolr::mission
