#include "SyntheticTurntable.h"

#include <mrolr/model/ModelStats.h>
#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/WireFrameIO.h>

#include <mrpt/config/CConfigFile.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

using namespace mrolr;
using namespace mrolr::model;

using namespace mrolr::model::test;

TEST(Turntable, BoxModelFromEightViewsMeetsTheTargets)
{
	const std::string dir = ::testing::TempDir() + "turntable_box";
	writeTurntableDir(dir);
	const TurntableSet set = loadTurntableSet(dir);
	ASSERT_EQ(set.views.size(), 8u);
	const WireFrame wf = buildFromTurntable(set, stereo::SceneOptions(), TurntableOptions());
	const ModelQuality q = compareToTruth(wf, loadWireFrame(set.truth_path));
	printQuality(q, std::cout);
	std::cout << "features " << wf.lines.size() << " lines " << wf.conics.size() << " conics\n";
	saveWireFrame(wf, dir + "/built.wf");
	EXPECT_GE(q.recovered_fraction, 0.8);
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
	EXPECT_LE(q.false_features, 2);
}

TEST(Turntable, MissingKeysAreNamed)
{
	const std::string dir = ::testing::TempDir() + "turntable_bad";
	std::filesystem::create_directories(dir);
	std::ofstream(dir + "/turntable.ini") << "[turntable]\nobject = x\ncalib = c.ini\nviews = 1\n";
	try
	{
		loadTurntableSet(dir);
		ADD_FAILURE();
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("R_TfromL"), std::string::npos) << e.what();
	}
	EXPECT_THROW(loadTurntableSet("/nonexistent"), std::runtime_error);
}
