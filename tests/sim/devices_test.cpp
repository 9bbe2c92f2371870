#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/sim/SimHead.h>

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
base::LabmateModel noiselessModel()
{
	base::LabmateOptions o;
	o.velocity_noise_fraction = 0;
	return base::LabmateModel(o);
}
}  // namespace

TEST(SimBase, WithoutSlipOdometryFollowsTheTruthAndTicksCountTravel)
{
	sim::SimBaseOptions o;
	o.slip_probability = 0;
	sim::SimBase b(noiselessModel(), o);
	const base::WheelControl u{0.1, 0.1, 2.0};
	for (int i = 0; i < 5; ++i) b.step(u);
	EXPECT_LT((b.odometry().xv_zxphi - b.truePose()).norm(), 1e-4);
	EXPECT_NEAR(b.truePose().x(), 1.0, 1e-9);  // 5 × 0.2 m straight ahead along z
	EXPECT_EQ(b.odometry().ticks_right, long(1.0 * o.ticks_per_m));
	EXPECT_EQ(b.odometry().ticks_left, long(1.0 * o.ticks_per_m));
	EXPECT_DOUBLE_EQ(b.odometry().time_s, 10.0);
}

TEST(SimBase, SlipMovesTheTruthButNotTheEncoders)
{
	sim::SimBaseOptions o;
	o.slip_probability = 1;
	o.slip_fraction = 0.5;
	sim::SimBase slipping(noiselessModel(), o);
	const base::WheelControl u{0.1, 0.1, 2.0};
	for (int i = 0; i < 3; ++i) slipping.step(u);
	EXPECT_EQ(slipping.slipStepsSoFar(), 3);
	EXPECT_NEAR(slipping.odometry().xv_zxphi.x(), 0.6, 1e-4);  // odometry believes 0.6 m straight
	EXPECT_GT(std::abs(slipping.truePose().z() - slipping.odometry().xv_zxphi.z()), 1e-3);
	EXPECT_GT(std::abs(slipping.truePose()[0] - 0.6), 0.1);  // the truth fell short
}

TEST(SimBase, EncodersSeeTheVelocityNoiseSoOdometryDiffersFromTheCommands)
{
	sim::SimBaseOptions o;
	o.slip_probability = 0;
	const base::LabmateModel noisy;  // σ = 0.14 |v| (eq 5.13)
	sim::SimBase b(noisy, o);
	Eigen::Vector3d commanded = Eigen::Vector3d::Zero();
	for (int i = 0; i < 20; ++i)
	{
		const auto u = i % 5 == 4 ? noisy.rotationControl(0.3) : noisy.translationControl(0.2);
		b.step(u);
		commanded = noisy.move(commanded, u);
	}
	// without slip the encoders follow the wheels, and the wheels move the truth
	EXPECT_LT((b.odometry().xv_zxphi - b.truePose()).norm(), 1e-3);
	// the commands were not what the wheels did
	EXPECT_GT((b.odometry().xv_zxphi - commanded).head<2>().norm(), 0.02);
}

TEST(SimBase, ASlipBurstIsInvisibleToTheEncoders)
{
	// the same seed draws the same wheel noise and the same bursts; only the ground differs
	sim::SimBaseOptions grip, slip;
	grip.slip_probability = slip.slip_probability = 0.3;
	grip.slip_fraction = 0;
	slip.slip_fraction = 0.5;
	const base::LabmateModel noisy;
	sim::SimBase a(noisy, grip), b(noisy, slip);
	for (int i = 0; i < 20; ++i)
	{
		a.step(noisy.translationControl(0.2));
		b.step(noisy.translationControl(0.2));
	}
	ASSERT_GT(b.slipStepsSoFar(), 0);
	EXPECT_EQ(a.odometry().ticks_right, b.odometry().ticks_right);
	EXPECT_EQ(a.odometry().ticks_left, b.odometry().ticks_left);
	EXPECT_EQ(a.odometry().xv_zxphi, b.odometry().xv_zxphi);
	EXPECT_GT((b.truePose() - a.truePose()).head<2>().norm(), 0.05);  // the truth did slip
	EXPECT_GT((b.truePose() - b.odometry().xv_zxphi).head<2>().norm(), 0.05);
}

TEST(SimHead, MoveTimeFollowsTheSlowestJointAndLimitsAreEnforced)
{
	const geometry::BiSightHead head;
	sim::StereoRenderer r(head, {});
	mrpt::opengl::COpenGLScene scene;
	sim::SimHeadOptions o;
	sim::SimHead h(
	    r, scene, [] { return Eigen::Isometry3d::Identity(); }, o);
	const double t = h.moveTo({M_PI / 4, 0.1, -0.05, 0.05});  // 45° of pan at 90°/s
	EXPECT_NEAR(t, 0.5 + o.settle_s, 1e-9);
	EXPECT_THROW(h.moveTo({0, M_PI / 2, 0, 0}), geometry::GeometryError);  // tilt beyond 45°
	EXPECT_NEAR(h.angles().pan, M_PI / 4, 1e-12);  // a refused move leaves the head where it was
	const auto pair = h.grab();
	EXPECT_EQ(pair.left.getWidth(), 640u);
	EXPECT_EQ(pair.right.getHeight(), 480u);
}

TEST(SimArm, RefusesAJointBeyondItsLimitsAndWithoutPhysicsClosesOnNothing)
{
	// a stand-in kinematics: d1 lifts the gripper, q1 (deg) slides it along x by 1 mm per degree
	auto fk = [](const hw::ArmJoints& j)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = Eigen::Vector3d(j[1] * 1e-3, j[0] * 1e-3, 0.5);
		return T;
	};
	std::map<std::string, Eigen::Isometry3d> objects;
	objects["cup"] = Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.2, 0.5));
	sim::SimArm arm(fk, sim::SimArmOptions(), objects);
	EXPECT_EQ(arm.joints()[0], sim::SimArmOptions().max[0]) << "parked with the column at the top";
	EXPECT_FALSE(arm.docked()) << "the platform starts de-coupled (thesis 7.0)";
	EXPECT_THROW(arm.moveTo({200, 0, 0, 0, 0, 0, 0}), std::logic_error);
	EXPECT_THROW(arm.setGripper(true), std::logic_error);
	arm.dock(true);
	EXPECT_THROW(arm.moveTo({1000, 0, 0, 0, 0, 0, 0}), std::out_of_range);
	arm.moveTo({200, 0, 0, 0, 0, 0, 0});
	EXPECT_DOUBLE_EQ(arm.gripperWidthMm(), sim::SimArmOptions().open_width_mm);
	arm.setGripper(true);
	EXPECT_EQ(arm.grasped(), "");
	EXPECT_EQ(arm.gripperWidthMm(), 0.0);
}
