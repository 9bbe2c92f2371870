// The world side of a grasp: the gripper holds only what its open jaws straddle and whose width
// they close on; a finger that lands on the object or crosses a neighbour pushes it or knocks it
// over; a table stops the arm. The lab's own can, cube and bottle definitions, on a bench.
#include <mrolr/sim/GripperPhysics.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/sim/Placement.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

using namespace mrolr;

namespace
{
const std::string kObjects = std::string(MROLR_SOURCE_DIR) + "/datasets/objects/";

/** A bench 0.75 m high 1 m ahead of W's origin, and the named objects on it at (x, z) (m). */
struct Bench
{
	world::World world;
	std::map<std::string, world::ObjectShape> shapes;
	std::map<std::string, std::string> model_of;
	std::map<std::string, Eigen::Isometry3d> poses;
	sim::JawGeometry jaws{90, 40, 20};  // config/arm_rtx.ini [arm_grasp]
	std::unique_ptr<sim::GripperPhysics> physics;

	explicit Bench(const std::vector<std::tuple<std::string, std::string, double, double>>& objects)
	{
		world.tables.push_back({"bench", 0.0, 1.0, 0, 1.2, 0.8, 0.75, {}});
		for (const auto& [name, model, x, z] : objects)
		{
			world.objects.push_back({name, model, "bench", x, z, 0});
			shapes[model] = world::ObjectShape::load(kObjects + model + ".ini");
			model_of[name] = model;
		}
		poses = sim::placedObjectPoses(world);
		physics = std::make_unique<sim::GripperPhysics>(world, shapes, model_of, jaws,
		                                                sim::GripperPhysicsOptions{}, poses);
	}

	/** The gripper approaching along W's z, jaws closing along W's x, its grasp point at height
	 * @p h_mm above the bench at (x, z) (m). */
	static Eigen::Isometry3d gripperAt(double x, double z, double h_mm)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.linear().col(0) = -Eigen::Vector3d::UnitY();  // x_G down
		T.linear().col(1) = Eigen::Vector3d::UnitX();   // y_G: the closing axis
		T.linear().col(2) = Eigen::Vector3d::UnitZ();   // z_G: the approach
		T.translation() = Eigen::Vector3d(x, 0.75 + h_mm / 1000.0, z);
		return T;
	}

	/** The open gripper driven along W's z from @p back_m behind the end pose to it; the table
	 * it met, if any. */
	std::optional<std::string> approach(const Eigen::Isometry3d& T_end, double back_m)
	{
		Eigen::Isometry3d prev = T_end;
		prev.translation().z() -= back_m;
		const int n = static_cast<int>(back_m / 0.004) + 1;
		for (int k = 1; k <= n; ++k)
		{
			Eigen::Isometry3d T = T_end;
			T.translation().z() -= back_m * (1.0 - double(k) / n);
			if (auto t = physics->step(prev, T, jaws.opening_mm, "")) return t;
			prev = T;
		}
		return std::nullopt;
	}

	bool has(sim::GripperEvent::Kind kind, const std::string& object) const
	{
		for (const auto& e : physics->events())
			if (e.kind == kind && e.object == object) return true;
		return false;
	}
	double movedMm(const std::string& name) const
	{
		return 1000.0 * (poses.at(name).translation() -
		                 sim::placedObjectPoses(world).at(name).translation())
		                    .norm();
	}
};
}  // namespace

TEST(GripperPhysics, HoldsTheCanAndTheCubeWhenTheGraspIsRight)
{
	for (const auto& [model, h_mm, width_mm] : {std::tuple{"can", 60.0, 66.0}, {"alphabet_cube", 30.0, 60.0}})
	{
		Bench b({{"target", model, 0.0, 1.0}});
		const auto T = Bench::gripperAt(0.0, 1.0, h_mm);
		EXPECT_FALSE(b.approach(T, 0.15));
		const auto grip = b.physics->close(T);
		EXPECT_EQ(grip.object, "target") << model;
		EXPECT_NEAR(grip.width_mm, width_mm, 1.5) << model;
		EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Held, "target"));
		EXPECT_LT(b.movedMm("target"), 0.5) << model << ": the approach touched it";
	}
}

TEST(GripperPhysics, MissesWhenTheGraspIs30mmOffAcrossTheJaws)
{
	for (const auto& [model, h_mm] : {std::pair{"can", 60.0}, {"alphabet_cube", 30.0}})
	{
		Bench b({{"target", model, 0.0, 1.0}});
		const auto T = Bench::gripperAt(0.030, 1.0, h_mm);  // a finger comes down on the object
		EXPECT_FALSE(b.approach(T, 0.15));
		EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Pushed, "target")) << model;
		EXPECT_GT(b.movedMm("target"), 20) << model << ": the finger pushed it ahead";
		EXPECT_EQ(b.physics->close(T).object, "") << model << ": a pushed object is not straddled";
	}
}

TEST(GripperPhysics, ClosingOnACylindersChordSlipsOut)
{
	Bench b({{"target", "can", 0.0, 1.0}});
	// 40 mm short along the approach: the jaws reach a 52 mm chord of the 66 mm can
	const auto T = Bench::gripperAt(0.0, 1.0 - 0.040, 60.0);
	EXPECT_FALSE(b.approach(T, 0.10));
	EXPECT_EQ(b.physics->close(T).object, "");
	EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Slipped, "target"));
}

TEST(GripperPhysics, AnApproachThatCrossesANeighbourPushesItAndATallOneFalls)
{
	// a cube, then a bottle, stand before the can in the line of a finger (45 mm to the side)
	Bench b({{"target", "can", 0.0, 1.0}, {"cube", "alphabet_cube", 0.045, 0.88}});
	EXPECT_FALSE(b.approach(Bench::gripperAt(0.0, 1.0, 50.0), 0.30));
	EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Pushed, "cube"));
	EXPECT_GT(b.movedMm("cube"), 50);

	Bench tall({{"target", "can", 0.0, 1.0}, {"bottle", "bottle", 0.045, 0.85}});
	EXPECT_FALSE(tall.approach(Bench::gripperAt(0.0, 1.0, 170.0), 0.30));
	EXPECT_TRUE(tall.has(sim::GripperEvent::Kind::KnockedOver, "bottle"));
	const Eigen::Vector3d z_O = tall.poses.at("bottle").linear().col(2);
	EXPECT_NEAR(z_O.y(), 0.0, 1e-9) << "the fallen bottle lies on its side";
	EXPECT_GT(z_O.z(), 0.99) << "it fell away from the push";
}

TEST(GripperPhysics, ATableStopsTheFingers)
{
	Bench b({{"target", "can", 0.0, 1.0}});
	Eigen::Isometry3d above = Bench::gripperAt(0.2, 1.0, 30.0), into = above;
	into.translation().y() -= 0.05;  // the fingers' lower edges (10 mm below it) 30 mm into the top
	EXPECT_FALSE(b.physics->step(above, above, 90, ""));
	EXPECT_EQ(b.physics->step(above, into, 90, ""), std::optional<std::string>("bench"));
	EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Table, ""));
}

TEST(SimArmOptions, TheOldCaptureRadiusIsAnErrorNamingIt)
{
	mrpt::config::CConfigFileMemory cfg("[sim_arm]\ngrasp_radius_m = 0.1\n");
	sim::SimArmOptions o;
	try
	{
		o.loadFromConfigFile(cfg, "sim_arm");
		FAIL() << "grasp_radius_m was accepted";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("grasp_radius_m"), std::string::npos) << e.what();
	}
}

TEST(SimArm, ApproachesClosesLiftsAndCarriesWhatItHolds)
{
	// a stand-in kinematics: d1 (mm) is the grasp point's height above the bench, q1 (deg) moves
	// it along the approach by 1 mm per degree, ending at the can's axis at q1 = 0
	Bench b({{"target", "can", 0.0, 1.0}, {"other", "alphabet_cube", 0.3, 1.0}});
	auto fk = [](const hw::ArmJoints& j)
	{
		Eigen::Isometry3d T = Bench::gripperAt(0.0, 1.0, j[0]);
		T.translation().z() += j[1] * 1e-3;
		return T;
	};
	sim::SimArm arm(fk, sim::SimArmOptions(), b.poses, nullptr, b.physics.get());
	arm.dock(true);
	arm.moveTo({200, -150, 0, 0, 0, 0, 0});  // above and behind
	arm.moveTo({60, -150, 0, 0, 0, 0, 0});   // down to the pre-grasp
	arm.moveTo({60, 0, 0, 0, 0, 0, 0});      // in
	arm.setGripper(true);
	EXPECT_EQ(arm.grasped(), "target");
	EXPECT_NEAR(arm.gripperWidthMm(), 66, 1.5);
	const Eigen::Vector3d before = b.poses.at("target").translation();
	arm.moveTo({160, 0, 0, 0, 0, 0, 0});  // lift 100 mm
	EXPECT_NEAR(b.poses.at("target").translation().y() - before.y(), 0.100, 1e-9);
	EXPECT_LT(b.movedMm("other"), 1e-6);
	// a move down through the bench stops where the fingers meet it, the can still held
	EXPECT_THROW(arm.moveTo({0, 0, 0, 0, 0, 0, 0}), hw::ArmBlocked);
	EXPECT_GT(arm.joints()[0], 5.0) << "the fingers (10 mm below the grasp point) entered the bench";
	EXPECT_EQ(arm.grasped(), "target");
	// its platform does not leave with the object in the jaws
	EXPECT_THROW(arm.dock(false), std::logic_error);
	EXPECT_TRUE(arm.docked());
}

namespace
{
/** A deck 0.3 m high whose top centre stands at (x, z) (m), 0.7 × 0.8 m. */
sim::DeckSupport deckAt(double x, double z)
{
	sim::DeckSupport d;
	d.T_TopInW.translation() = Eigen::Vector3d(x, 0.3, z);
	d.half_x_m = 0.35, d.half_z_m = 0.4;
	return d;
}

/** Instance @p name lifted to @p y_m (its origin, the bottom centre) over (x, z), upright. */
void holdAt(Bench& b, const std::string& name, double x, double y_m, double z)
{
	b.poses.at(name).translation() = Eigen::Vector3d(x, y_m, z);
}
}  // namespace

TEST(GripperPhysics, LetGoOverTheDeckTheObjectRestsOnItAndElsewhereOnWhatIsUnder)
{
	Bench b({{"cube", "alphabet_cube", 0.0, 1.0}, {"can", "can", 0.2, 1.0}});
	const auto deck = deckAt(2.0, 0.0);  // away from the bench
	holdAt(b, "cube", 2.1, 0.305, -0.2);  // 5 mm above the deck
	EXPECT_TRUE(b.physics->release("cube", deck));
	EXPECT_NEAR(b.poses.at("cube").translation().y(), 0.3, 1e-12);
	EXPECT_NEAR(b.poses.at("cube").linear().col(2).y(), 1.0, 1e-12) << "it stays upright";
	EXPECT_TRUE(b.has(sim::GripperEvent::Kind::Released, "cube"));
	EXPECT_FALSE(b.has(sim::GripperEvent::Kind::KnockedOver, "cube"));
	holdAt(b, "can", 0.2, 0.76, 1.0);  // back over the bench: onto its top, not the deck
	EXPECT_FALSE(b.physics->release("can", deck));
	EXPECT_NEAR(b.poses.at("can").translation().y(), 0.75, 1e-12);
	holdAt(b, "cube", 2.1, 0.01, 0.6);  // beside the deck, below its top: to the floor
	EXPECT_FALSE(b.physics->release("cube", deck));
	EXPECT_NEAR(b.poses.at("cube").translation().y(), 0.0, 1e-12);
}

TEST(GripperPhysics, ATallObjectLetGoFromHighFallsOver)
{
	Bench b({{"bottle", "bottle", 0.0, 1.0}});
	holdAt(b, "bottle", 2.0, 0.30 + sim::GripperPhysics::kGentleDrop_mm / 1000.0 + 0.1, 0.0);
	EXPECT_TRUE(b.physics->release("bottle", deckAt(2.0, 0.0)));  // still on the deck…
	EXPECT_TRUE(b.has(sim::GripperEvent::Kind::KnockedOver, "bottle"));  // …on its side
	EXPECT_LT(std::abs(b.poses.at("bottle").linear().col(2).y()), 1e-9);
}
