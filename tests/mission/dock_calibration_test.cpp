// Calibrating the dock (thesis eq 6.7.2 over several poses): the arm presents its hand's ArUco
// marker round the object, the head triangulates it in rendered pairs, and the fitted T_C0inA
// recovers the dock error the simulated lab injected; with the marker hidden from the head, the
// calibration is refused with its reason and the nominal mount kept.
#include <mrolr/arm/MountCalibration.h>
#include <mrolr/mission/DockCalibration.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/sim/Lab.h>

#include <mrolr/util/Config.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

using namespace mrolr;

namespace
{
mrpt::config::CConfigFileMemory missionFile(unsigned seed)
{
	mrpt::config::CConfigFileMemory cfg(
	    util::openConfigFile(std::string(MROLR_SOURCE_DIR) + "/config/mission_sim.ini").getContent());
	cfg.write("mission", "seed", std::to_string(seed));
	return cfg;
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
	return Eigen::AngleAxisd(a.transpose() * b).angle() * 180.0 / M_PI;
}

struct Outcome
{
	mission::DockCalibrationResult result;
	Eigen::Isometry3d T_true, T_nominal;
};

Outcome calibrateOnLab(unsigned seed, bool draw_arm = true)
{
	auto cfg = missionFile(seed);
	cfg.write("sim_arm", "draw_arm", draw_arm ? "true" : "false");
	cfg.write("sim_arm", "mount_error_mm", "20");
	cfg.write("sim_arm", "mount_error_deg", "2");
	cfg.write("dock_calibration", "enabled", "true");
	const auto dir = std::string(MROLR_SOURCE_DIR) + "/config";
	const auto lab_o = sim::LabOptions::load(cfg, dir);
	const auto o = mission::MissionOptions::fromConfig(cfg, dir);
	sim::Lab lab(lab_o);
	const geometry::BiSightHead head(o.bisight);
	const mission::DockCalibrator cal(o.dock_calibration, o.rtx, o.grasp, o.marker, head, 1.0, 1.0);
	auto look = [&lab](const geometry::HeadAngles& a)
	{
		lab.head().moveTo(a);
		return lab.head().grab();
	};
	// an object 0.75 m ahead on a table top 0.25 m below the head, as at a search station
	const Eigen::Vector3d p_OinC0_mm(0, -250, 750);
	const double table_z_in_A = (o.dock.T_C0inA * Eigen::Vector3d(0, -250, 0)).z();
	mission::Timeline t;
	lab.arm().dock(true);
	return {cal.run(lab.arm(), look, o.dock.T_C0inA, p_OinC0_mm, table_z_in_A, t),
	        lab.trueMount(), o.dock.T_C0inA};
}
}  // namespace

TEST(MountFit, RecoversARigidTransformFromExactPointsAndRefusesALine)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(-300, 120, 711);
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> u(-300, 300);
	std::vector<Eigen::Vector3d> a, c;
	for (int k = 0; k < 6; ++k)
	{
		c.emplace_back(u(rng), u(rng), u(rng));
		a.push_back(T * c.back());
	}
	const auto fit = arm::fitHeadInArm(a, c);
	EXPECT_LT((fit.T_C0inA.translation() - T.translation()).norm(), 1e-6);
	EXPECT_LT(angleDeg(fit.T_C0inA.linear(), T.linear()), 1e-6);
	EXPECT_LT(fit.rms_mm, 1e-6);
	std::vector<Eigen::Vector3d> line_c, line_a;
	for (int k = 0; k < 4; ++k)
	{
		line_c.emplace_back(10.0 * k, 20.0 * k, 0);
		line_a.push_back(T * line_c.back());
	}
	EXPECT_THROW(arm::fitHeadInArm(line_a, line_c), std::invalid_argument);
	EXPECT_THROW(arm::fitHeadInArm({a[0], a[1]}, {c[0], c[1]}), std::invalid_argument);
}

TEST(DockCalibration, RecoversTheInjectedDockErrorOnTheLab)
{
	for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u})
	{
		const auto out = calibrateOnLab(seed);
		const auto& r = out.result;
		ASSERT_TRUE(r.calibrated) << "seed " << seed << ": " << r.reason;
		const double before_mm = (out.T_nominal.translation() - out.T_true.translation()).norm();
		const double after_mm = (r.T_C0inA.translation() - out.T_true.translation()).norm();
		const double after_deg = angleDeg(r.T_C0inA.linear(), out.T_true.linear());
		std::cout << "seed " << seed << ": dock error " << before_mm << " mm, "
		          << angleDeg(out.T_nominal.linear(), out.T_true.linear()) << " deg; calibrated "
		          << after_mm << " mm, " << after_deg << " deg from " << r.sightings << " of "
		          << r.poses_planned << " poses, rms " << r.fit.rms_mm << " mm\n";
		EXPECT_GT(before_mm, 5.0) << "seed " << seed << ": the lab injected no dock error";
		EXPECT_LT(after_mm, 4.0) << "seed " << seed << " (dock error " << before_mm << " mm)";
		EXPECT_LT(after_deg, 0.4) << "seed " << seed;
		EXPECT_GE(r.sightings, 4);
		EXPECT_LT(r.fit.rms_mm, 2.0);
	}
}

TEST(DockCalibration, WithoutTheArmInTheImagesItIsRefusedAndTheNominalKept)
{
	const auto out = calibrateOnLab(1, /*draw_arm=*/false);
	EXPECT_FALSE(out.result.calibrated);
	EXPECT_EQ(out.result.sightings, 0);
	EXPECT_NE(out.result.reason.find("seen in both images at 0 of"), std::string::npos)
	    << out.result.reason;
	EXPECT_TRUE(out.result.T_C0inA.isApprox(out.T_nominal));
}
