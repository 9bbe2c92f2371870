// Putting the retrieved object on board: for each of the thesis's objects the planner finds a spot
// on the shipped robot's deck, the object comes down upright drop_mm above it, and the whole
// motion is free of the deck, the mast and the arm itself when tested five times finer than
// planned; a deck with no room gives no plan and says why; a pose through the mast is refused.
#include <mrolr/arm/GraspChain.h>
#include <mrolr/mission/DeckPlacement.h>
#include <mrolr/model/WireFrameIO.h>
#include "MissionTestConfig.h"

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
struct Held
{
	arm::RtxJoints lifted;
	Eigen::Isometry3d T_GinO_mm = Eigen::Isometry3d::Identity();
};

/** The object upright 0.12 m above a table top 0.75 m high, at (x, z) (m) in C0, held at its
 * model's grasp turned by the first of 0, ±45, … that the arm reaches. */
std::optional<Held> liftedAt(const mission::MissionOptions& o, const model::WireFrame& wf,
                             double x, double z)
{
	Eigen::Isometry3d T_OinC0 = Eigen::Isometry3d::Identity();
	T_OinC0.linear().col(0) = Eigen::Vector3d::UnitZ();
	T_OinC0.linear().col(1) = Eigen::Vector3d::UnitX();
	T_OinC0.linear().col(2) = Eigen::Vector3d::UnitY();
	T_OinC0.translation() = 1000.0 * Eigen::Vector3d(x, 0.75 + 0.12 - o.bisight.head_height_m, z);
	const arm::AnalyticIk ik(o.rtx);
	for (double turn : {0.0, 45.0, -45.0, 90.0, -90.0, 135.0, -135.0, 180.0})
	{
		const Eigen::Isometry3d T_GinO =
		    Eigen::AngleAxisd(turn * M_PI / 180, Eigen::Vector3d::UnitZ()) * arm::graspInObject(wf.grasp);
		const auto r = ik.solve(o.dock.T_C0inA * T_OinC0 * T_GinO);
		if (!r.solutions.empty()) return Held{r.solutions.front().joints, T_GinO};
	}
	return std::nullopt;
}

/** The simulated arm's parked joints: the column at the top, every angle 0 (config/mission_sim.ini). */
arm::RtxJoints parked()
{
	return arm::RtxJoints::fromMmDeg({925, 0, 0, 0, 0, 0, 0});
}

model::WireFrame modelOf(const mission::MissionOptions& o, const std::string& name)
{
	return model::loadWireFrame(o.models_dir + "/" + name + ".wf");
}
}  // namespace

TEST(DeckPlacement, EachObjectIsPutDownUprightByAMotionFreeAtAFinerStep)
{
	auto cfg = mission::test::defaultMissionConfig();
	const auto o = mission::test::optionsFrom(cfg);
	auto finer = o;
	finer.place.check_step_mm = o.place.check_step_mm / 5;
	for (const char* name : {"alphabet_cube", "drink_package", "can", "bottle"})
	{
		SCOPED_TRACE(name);
		const auto wf = modelOf(o, name);
		const auto held = liftedAt(o, wf, -0.3, 0.7);
		ASSERT_TRUE(held) << "no lifted pose in reach";
		const mission::DeckPlacement deck(o, wf, o.dock.T_C0inA);
		const auto plan = deck.plan(held->lifted, held->T_GinO_mm, parked());
		ASSERT_TRUE(plan.found) << plan.reason;
		// the object's origin (its bottom centre) drop_mm above the deck's top, on the deck, upright
		const arm::RtxKinematics kin(o.rtx);
		const Eigen::Isometry3d T_OinC0 = o.dock.T_C0inA.inverse() * kin.T06(plan.carry.back()) *
		                                  held->T_GinO_mm.inverse();
		const double deck_top_y = 1000.0 * (o.labmate.deck_height_m - o.bisight.head_height_m);
		// (a built model's bottom lies within a millimetre or two of its origin)
		EXPECT_NEAR(T_OinC0.translation().y(), deck_top_y + plan.drop_mm, 2.0);
		EXPECT_GE(plan.drop_mm, o.place.drop_mm);
		EXPECT_LE(plan.drop_mm, 25.0) << "let go low enough to stay standing";
		EXPECT_NEAR(T_OinC0.linear().col(2).y(), 1.0, 1e-6);
		EXPECT_LE(std::abs(T_OinC0.translation().x()), 500.0 * o.labmate.footprint_width_m);
		EXPECT_LE(std::abs(T_OinC0.translation().z()), 500.0 * o.labmate.footprint_length_m);
		EXPECT_LT(T_OinC0.translation().z(), 0.0) << "rearmost spots first: behind the head";
		// the whole motion, five times finer
		const mission::DeckPlacement check(finer, wf, o.dock.T_C0inA);
		int tested = 0;
		arm::RtxJoints from = held->lifted;
		for (const auto& j : plan.carry)
		{
			EXPECT_EQ(check.contactAlong(from, j, held->T_GinO_mm, o.place.drop_mm / 2, tested), "");
			from = j;
		}
		for (const auto& j : plan.leave)
		{
			EXPECT_EQ(check.contactAlong(from, j, std::nullopt, 0, tested), "");
			from = j;
		}
		EXPECT_GT(tested, plan.tested_poses / 10);
		const auto end = plan.leave.back().toMmDeg(), park = parked().toMmDeg();
		for (size_t i = 0; i < end.size(); ++i) EXPECT_NEAR(end[i], park[i], 1e-9) << "parked again";
	}
}

TEST(DeckPlacement, ADeckWithNoRoomGivesNoPlanAndSaysWhy)
{
	auto cfg = mission::test::defaultMissionConfig();
	auto o = mission::test::optionsFrom(cfg);
	const auto wf = modelOf(o, "alphabet_cube");
	const auto held = liftedAt(o, wf, -0.3, 0.7);
	ASSERT_TRUE(held);
	o.labmate.footprint_width_m = o.labmate.footprint_length_m = 0.25;  // the mast fills it
	const mission::DeckPlacement deck(o, wf, o.dock.T_C0inA);
	const auto plan = deck.plan(held->lifted, held->T_GinO_mm, parked());
	EXPECT_FALSE(plan.found);
	EXPECT_NE(plan.reason.find("spots on the deck"), std::string::npos) << plan.reason;
}

TEST(DeckPlacement, AnArmThroughTheMastOrTheDeckIsAContact)
{
	auto cfg = mission::test::defaultMissionConfig();
	const auto o = mission::test::optionsFrom(cfg);
	const auto wf = modelOf(o, "alphabet_cube");
	const auto held = liftedAt(o, wf, -0.3, 0.7);
	ASSERT_TRUE(held);
	const mission::DeckPlacement deck(o, wf, o.dock.T_C0inA);
	const auto plan = deck.plan(held->lifted, held->T_GinO_mm, parked());
	ASSERT_TRUE(plan.found) << plan.reason;
	// the release pose lowered by 40 mm: the hand, the links or the object enter the deck
	arm::RtxJoints low = plan.carry.back();
	EXPECT_EQ(deck.contactAt(low, held->T_GinO_mm, o.place.drop_mm / 2), "");
	low.d1_mm -= 40;
	EXPECT_NE(deck.contactAt(low, held->T_GinO_mm, o.place.drop_mm / 2).find("deck"),
	          std::string::npos);
	// an arm mounted 0.3 m ahead of the head facing back, stretched out over the head at
	// mid-height of the mast: its links pass through the mast
	Eigen::Isometry3d T_C0inA = Eigen::Isometry3d::Identity();
	T_C0inA.linear() << 0, 0, -1, -1, 0, 0, 0, 1, 0;
	T_C0inA.translation() = Eigen::Vector3d(300, 0, 711);
	const mission::DeckPlacement behind(o, wf, T_C0inA);
	const auto stretched = arm::RtxJoints::fromMmDeg({411, 0, 0, 0, 0, 90, 0});
	EXPECT_NE(behind.contactAt(stretched, std::nullopt, 0).find("mast"), std::string::npos)
	    << behind.contactAt(stretched, std::nullopt, 0);
	const auto above = arm::RtxJoints::fromMmDeg({925, 0, 0, 0, 0, 90, 0});  // over the head
	EXPECT_EQ(behind.contactAt(above, std::nullopt, 0), "");
}
