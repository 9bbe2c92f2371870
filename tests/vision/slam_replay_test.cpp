// mrolr-slam --rawlog (issue 5): a short mrolr-sim recording of maps/lab replayed through the
// vision pipeline ends closer to the truth than the recording's own dead reckoning, and the MRPT
// outputs (decisions.rawlog, slam.3Dscene) read back with the expected counts.
#include <mrolr/apps/SimApp.h>
#include <mrolr/apps/SlamApp.h>
#include <mrolr/util/Cli.h>

#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/opengl/CEllipsoid3D.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using mrolr::apps::SlamApp;

namespace
{
const std::string kRoot = MROLR_SOURCE_DIR;
constexpr int kRecordedSteps = 20;

/** A fresh folder per test (ctest runs the tests of this file in parallel processes). */
fs::path testDir()
{
	const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
	const fs::path dir =
	    fs::temp_directory_path() / ("mrolr_slam_replay_" + std::string(info->name()));
	fs::remove_all(dir);
	fs::create_directories(dir);
	return dir;
}

/** config/sim.ini with wheel slip on most steps: the encoders count what the wheels turned, so
 * only slip (which they do not see) makes the recording's dead reckoning drift. */
std::string slippyConfig(const fs::path& dir)
{
	std::ifstream in(kRoot + "/config/sim.ini");
	const std::string path = (dir / "sim.ini").string();
	std::ofstream out(path);
	for (std::string line; std::getline(in, line);)
		out << (line.rfind("slip_probability =", 0) == 0 ? "slip_probability = 0.5" : line) << "\n";
	return path;
}

std::string record(const fs::path& dir)
{
	const std::string path = (dir / "run.rawlog").string();
	mrolr::apps::SimApp sim;
	sim.initialize({"mrolr-sim", "--world", kRoot + "/maps/lab/world.ini", "--out", path,
	                "--max-steps", std::to_string(kRecordedSteps), "--config",
	                slippyConfig(dir), "--json"});
	std::ostringstream out;
	EXPECT_EQ(sim.run(out), 0);
	return path;
}

SlamApp replay(const std::string& rawlog, const fs::path& out_dir)
{
	SlamApp app;
	app.initialize({"mrolr-slam", "--rawlog", rawlog, "--world", kRoot + "/maps/lab/world.ini",
	                "--out", out_dir.string()});
	std::ostringstream out;
	EXPECT_EQ(app.run(out), 0);
	return app;
}
}  // namespace

TEST(SlamReplay, ShortRecordingEndsCloserThanItsDeadReckoning)
{
	const fs::path dir = testDir();
	const SlamApp app = replay(record(dir), dir / "out");
	const auto& s = app.summary;
	EXPECT_EQ(s.cycles, kRecordedSteps + 1);      // one cycle per rawlog record
	EXPECT_GT(s.dr_final_position_error_m, 0.2);  // the recording's odometry really drifted
	EXPECT_LT(s.slam_final_position_error_m, 0.6 * s.dr_final_position_error_m);
	EXPECT_GE(s.features, 3);
	EXPECT_GE(s.measurements, 10);
	EXPECT_GT(s.match_success_rate, 0.5);
}

TEST(SlamReplay, DecisionsRawlogAndSceneReadBack)
{
	const fs::path dir = testDir();
	const SlamApp app = replay(record(dir), dir / "out");
	mrpt::obs::CRawlog log;
	ASSERT_TRUE(log.loadFromRawLogFile((dir / "out" / "decisions.rawlog").string()));
	size_t comments = 0, frames = 0, estimates = 0;
	for (size_t i = 0; i < log.size(); ++i)
	{
		if (log.getType(i) != mrpt::obs::CRawlog::etSensoryFrame) continue;
		const auto sf = log.getAsObservations(i);
		++frames;
		for (const auto& o : *sf)
		{
			if (const auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(o))
			{
				++comments;
				EXPECT_EQ(c->text.rfind("step=", 0), 0u) << c->text;
				EXPECT_NE(c->text.find(" accepted="), std::string::npos) << c->text;
			}
			estimates += o->sensorLabel == "SLAM_ESTIMATE";
		}
	}
	size_t records = 0;
	for (const auto& st : app.steps) records += st.records.size();
	EXPECT_EQ(frames, app.steps.size());
	EXPECT_EQ(estimates, app.steps.size());
	EXPECT_EQ(comments, records);

	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile((dir / "out" / "slam.3Dscene").string()));
	size_t ellipsoids = 0;
	for (const auto& f : app.map)
		ellipsoids += bool(std::dynamic_pointer_cast<mrpt::opengl::CEllipsoid3D>(
		    scene.getByName("map." + f.label)));
	EXPECT_EQ(ellipsoids, app.map.size());
	for (const char* name : {"path.true", "path.estimate", "path.dead_reckoning"})
	{
		const auto lines =
		    std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(scene.getByName(name));
		ASSERT_TRUE(lines) << name;
		EXPECT_EQ(lines->getLineCount(), app.steps.size() - 1) << name;
	}
	EXPECT_TRUE(scene.getByName("landmarks.true"));
}

TEST(SlamReplay, BadInputIsReported)
{
	SlamApp missing;
	missing.initialize({"mrolr-slam", "--rawlog", "/nonexistent/run.rawlog"});
	std::ostringstream out;
	try
	{
		missing.run(out);
		FAIL() << "a missing rawlog must throw";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/run.rawlog"), std::string::npos);
	}
	SlamApp app;
	EXPECT_THROW(app.initialize({"mrolr-slam", "--rawlog", "r.rawlog", "--head", "lab"}),
	             mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"mrolr-slam", "--rawlog", "r.rawlog", "--live", "--world", "w"}),
	             mrolr::util::UsageError);
}
