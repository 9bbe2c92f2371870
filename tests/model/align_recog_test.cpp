// Thesis 6.5: turntable views integrated by recognition (apps/RecognitionAlignment.h), on the
// rendered box turntable of SyntheticTurntable.h (100×70×60 mm, 8 views 45° apart).
#include "SyntheticTurntable.h"

#include <mrolr/apps/ModelApp.h>
#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Cli.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <iostream>
#include <sstream>

using namespace mrolr;
using apps::AlignmentResult;
using apps::ViewRegistration;

namespace
{
std::string boxDir(const std::string& name)
{
	const std::string dir = ::testing::TempDir() + "align_recog_" + name;
	model::test::writeTurntableDir(dir);
	return dir;
}

/** Overwrites view @p v of @p dir with a rendering of the empty table. */
void emptyView(const std::string& dir, int v)
{
	cv::Mat L, R;
	const auto faces = model::test::viewFaces(45.0 * v);
	stereo::test::renderPair({faces.front()}, stereo::test::testRig(), L, R, false);
	const std::string stem = dir + "/view_" + std::to_string(v);
	cv::imwrite(stem + "_left.png", L);
	cv::imwrite(stem + "_right.png", R);
}

apps::AlignOptions matching(const std::string& match)
{
	apps::AlignOptions ao;
	ao.match = match;
	return ao;
}

AlignmentResult build(const std::string& dir, const apps::AlignOptions& ao)
{
	const auto set = model::loadTurntableSet(dir);
	const auto truth = model::loadWireFrame(set.truth_path);
	mrpt::config::CConfigFile cfg("config/model.ini");
	stereo::SceneOptions so;
	so.loadFromConfigFile(cfg, "scene");
	model::TurntableOptions to;
	to.loadFromConfigFile(cfg, "turntable");
	return apps::buildByRecognition(set, so, to, ao, &truth);
}

void print(const AlignmentResult& r)
{
	for (const auto& v : r.views)
		std::cout << "view " << v.view << " at " << v.known_angle_deg
		          << " deg: " << (v.registered ? "registered" : "NOT registered: " + v.reason)
		          << ", turn " << v.turn_deg << " deg, error " << v.rot_err_deg << " deg "
		          << v.trans_err_mm << " mm (symmetry " << v.symmetry_deg << " deg), score "
		          << v.score << "\n";
}
}  // namespace

/** Every view registered, within @p max_deg and @p max_mm of its known turn modulo the box's
 * 180° symmetry; the model meets issue 6's targets. */
void expectEveryViewRegistered(const AlignmentResult& r, double max_deg, double max_mm)
{
	print(r);
	ASSERT_EQ(r.views.size(), 8u);
	EXPECT_EQ(r.registered, 8u);
	for (const auto& v : r.views)
	{
		EXPECT_TRUE(v.registered) << "view " << v.view << ": " << v.reason;
		EXPECT_LT(v.rot_err_deg, max_deg) << "view " << v.view;
		EXPECT_LT(v.trans_err_mm, max_mm) << "view " << v.view;
		const double d = std::remainder(v.turn_deg + v.symmetry_deg - v.known_angle_deg, 360.0);
		EXPECT_LT(std::abs(d), max_deg) << "view " << v.view;
	}
	const auto q = model::compareToTruth(r.model, model::test::boxTruth());
	model::printQuality(q, std::cout);
	EXPECT_GE(q.recovered_fraction, 0.8);
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
}

TEST(AlignRecog, EveryBoxViewRegistersNearItsKnownAngleIn3D)
{
	expectEveryViewRegistered(build(boxDir("all_3d"), matching("shorter")), 4.0, 5.0);
}

TEST(AlignRecog, EveryBoxViewRegistersNearItsKnownAngleInTheImages)
{
	// the image refinement pulls the translation towards image edges: a few mm looser than 3D
	expectEveryViewRegistered(build(boxDir("all_images"), matching("images")), 4.0, 12.0);
}

TEST(AlignRecog, AnEmptyViewIsReportedNotMerged)
{
	const std::string dir = boxDir("empty_view");
	emptyView(dir, 3);
	const auto r = build(dir, matching("shorter"));
	print(r);
	EXPECT_FALSE(r.views[3].registered);
	EXPECT_FALSE(r.views[3].reason.empty());
	EXPECT_EQ(r.views[3].features, 0u);
	EXPECT_EQ(r.registered, 7u);
	const auto q = model::compareToTruth(r.model, model::test::boxTruth());
	EXPECT_GE(q.recovered_fraction, 0.8);
}

TEST(AlignRecog, AnEmptySeedIsAnErrorNamingIt)
{
	const std::string dir = boxDir("empty_seed");
	emptyView(dir, 0);
	try
	{
		build(dir, matching("shorter"));
		ADD_FAILURE() << "no error for an empty first view";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("seed view 0 has 0 features"), std::string::npos)
		    << e.what();
	}
	auto ao = matching("shorter");
	ao.seed_view = 8;
	EXPECT_THROW(build(dir, ao), std::invalid_argument);
}

TEST(AlignRecog, ErrorIsMeasuredModuloTheObjectsSymmetry)
{
	const model::WireFrame box = model::test::boxTruth();
	auto registration = [&](double turn_error_deg)
	{
		ViewRegistration r;
		r.known_angle_deg = 45;
		r.T_VinM = Eigen::AngleAxisd((turn_error_deg - 45) * M_PI / 180, Eigen::Vector3d::UnitZ());
		apps::measureRegistrationError(r, box, &box);
		return r;
	};
	const auto flipped = registration(180), quarter = registration(90), off = registration(2);
	EXPECT_NEAR(std::abs(flipped.symmetry_deg), 180, 1e-9);
	EXPECT_NEAR(flipped.rot_err_deg, 0, 1e-6);
	EXPECT_NEAR(flipped.trans_err_mm, 0, 1e-6);
	EXPECT_EQ(quarter.symmetry_deg, 0);  // 100×70 mm: a quarter turn is no symmetry
	EXPECT_NEAR(quarter.rot_err_deg, 90, 1e-6);
	EXPECT_NEAR(off.rot_err_deg, 2, 1e-6);
	EXPECT_GT(off.trans_err_mm, 0);
}

TEST(AlignRecog, OptionsAreReadAndCheckedByKey)
{
	apps::AlignOptions o;
	o.loadFromConfigFile(mrpt::config::CConfigFile("config/model.ini"), "align");
	EXPECT_GE(o.passes, 1);
	EXPECT_FALSE(apps::alignmentRecognitionOptions(matching("shorter")).verify_visible_only);
	for (const std::string key : {"passes = 0", "match = icp", "seed_view = -1"})
	{
		mrpt::config::CConfigFileMemory bad;
		bad.setContent("[align]\n" + key + "\n");
		try
		{
			apps::AlignOptions().loadFromConfigFile(bad, "align");
			ADD_FAILURE() << key;
		}
		catch (const std::exception& e)
		{
			const std::string name = key.substr(0, key.find(' '));
			EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
		}
	}
}

TEST(AlignRecog, AppRejectsAnUnknownAlignMethod)
{
	apps::ModelApp app;
	try
	{
		app.initialize(
		    {"mrolr-model", "build", "--turntable", "D", "--out", "M.wf", "--align", "icp"});
		ADD_FAILURE();
	}
	catch (const util::UsageError& e)
	{
		EXPECT_NE(std::string(e.what()).find("--align"), std::string::npos) << e.what();
	}
	EXPECT_EQ(util::runMain("mrolr-model",
	                        [&]
	                        {
		                        app.initialize({"mrolr-model", "build", "--turntable", "D", "--out",
		                                        "M.wf", "--align", "icp"});
		                        return 0;
	                        }),
	          2);
}

TEST(AlignRecog, AppReportsEveryViewsRegistration)
{
	const std::string dir = boxDir("app");
	emptyView(dir, 5);
	apps::ModelApp app;
	app.initialize({"mrolr-model", "build", "--turntable", dir, "--out", dir + "/M.wf", "--align",
	                "recog", "--json"});
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0);
	const auto j = nlohmann::json::parse(out.str());
	ASSERT_EQ(j["registration"].size(), 8u);
	EXPECT_EQ(j["align"], "recog");
	EXPECT_EQ(j["views_registered"], 7);
	EXPECT_TRUE(j["registration"][1]["seed"].get<bool>());  // config/model.ini: seed_view = 1
	EXPECT_FALSE(j["registration"][5]["registered"].get<bool>());
	EXPECT_TRUE(j["registration"][5].contains("reason"));
	EXPECT_GE(j["quality"]["recovered_fraction"].get<double>(), 0.7);  // from the seven other views
	EXPECT_TRUE(std::filesystem::exists(dir + "/M.wf"));
}
