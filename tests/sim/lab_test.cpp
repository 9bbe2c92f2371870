// The simulated lab, world side: the gripper reports what its jaws meet, the head renders with
// noise that changes per frame and logs each frame's truth, a simulated sensor is chosen by
// name, and every random draw follows the run's seed.
#include <mrolr/sim/JawWidth.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/sim/SimulatedSensors.h>

#include <mrolr/util/Config.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/core.hpp>

#include <fstream>
#include <sstream>

using namespace mrolr;

namespace
{
mrpt::config::CConfigFileMemory missionFile()
{
	return mrpt::config::CConfigFileMemory(
	    util::openConfigFile(std::string(MROLR_SOURCE_DIR) + "/config/mission_sim.ini").getContent());
}

sim::LabOptions labOptions(unsigned seed)
{
	auto cfg = missionFile();
	cfg.write("mission", "seed", std::to_string(seed));
	return sim::LabOptions::load(cfg, std::string(MROLR_SOURCE_DIR) + "/config");
}

world::ObjectShape cube()
{
	return world::ObjectShape::parse("[object]\nname = c\n[part.p]\ntype = box\nbase_mm = 0 0 0\n"
	                                 "size_mm = 60 60 60\n");
}
}  // namespace

TEST(JawWidth, ClosingOnACubeAcrossItsFacesGivesItsWidthAndBesideItNothing)
{
	const sim::JawGeometry jaws{90, 40, 20};
	// the gripper at the cube's middle, jaws closing along O's y
	Eigen::Isometry3d T_OinG = Eigen::Isometry3d::Identity();
	T_OinG.translation() = Eigen::Vector3d(0, 0, -30);
	EXPECT_NEAR(sim::jawWidthMm(cube(), T_OinG, jaws), 60, 1.0);
	// turned 45 deg about the vertical: the diagonal, 85 mm, still fits the 90 mm jaws
	T_OinG.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	EXPECT_NEAR(sim::jawWidthMm(cube(), T_OinG, jaws), 60 * std::sqrt(2.0), 2.5);
	// 10 cm beside it the jaws meet
	T_OinG = Eigen::Isometry3d::Identity();
	T_OinG.translation() = Eigen::Vector3d(100, 0, -30);
	EXPECT_EQ(sim::jawWidthMm(cube(), T_OinG, jaws), 0);
}

TEST(Lab, EveryGrabIsNoisyDifferentlyAndLogsItsTruth)
{
	sim::Lab lab(labOptions(1));
	EXPECT_DOUBLE_EQ(lab.options().render.noise_sigma_grey, 2.0);
	const auto a = lab.head().grab();
	const auto b = lab.head().grab();
	EXPECT_EQ(a.frame + 1, b.frame);
	const cv::Mat ma = a.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat mb = b.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	EXPECT_GT(cv::norm(ma, mb, cv::NORM_L1), 0) << "the same view, the same noise";
	ASSERT_EQ(lab.truth().frames.size(), 2u);
	EXPECT_EQ(lab.truth().frames[1].frame, b.frame);
	EXPECT_EQ(lab.truth().frames[0].T_OinW.size(), lab.objectPoses().size());
}

TEST(Lab, TheRunsSeedChangesTheWorldsDraws)
{
	sim::Lab one(labOptions(1)), two(labOptions(2));
	for (auto* lab : {&one, &two})
		for (int k = 0; k < 20; ++k) lab->base().step({0.1, 0.1, 2.0});
	EXPECT_NE(one.truePose(), two.truePose());
	sim::Lab again(labOptions(1));
	for (int k = 0; k < 20; ++k) again.base().step({0.1, 0.1, 2.0});
	EXPECT_EQ(one.truePose(), again.truePose());
}

TEST(SimulatedSensors, AnUnknownNameIsAnErrorNamingTheChoices)
{
	sim::Lab lab(labOptions(1));
	EXPECT_THROW(sim::makeLandmarkSensor("ideal", lab, {}), std::invalid_argument);
	EXPECT_THROW(sim::makeSceneSensor("exact", lab, {}), std::invalid_argument);
	try
	{
		sim::makeLandmarkSensor("truth", lab, {});
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("ideal_sim"), std::string::npos);
	}
	const auto ideal = sim::makeLandmarkSensor("ideal_sim", lab, {});
	EXPECT_FALSE(ideal->visible().empty());
}
