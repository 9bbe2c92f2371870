// mrolr-sim's app class run inside tests: snapshot truth against its own images, a short recording
// read back, and argument errors.
#include <mrolr/apps/SimApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using mrolr::apps::SimApp;
namespace fs = std::filesystem;

namespace
{
const std::string kLab = std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini";

std::string tempDir(const std::string& name)
{
	const auto d = fs::path(testing::TempDir()) / ("mrolr_sim_app_" + name);
	fs::remove_all(d);
	return d.string();
}

void runApp(const std::vector<std::string>& args, SimApp& app)
{
	std::vector<std::string> a{"mrolr-sim"};
	a.insert(a.end(), args.begin(), args.end());
	app.initialize(a);
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0) << out.str();
}

/** Normalised SSD of two 11×11 windows (0 = identical up to gain and offset). */
double nssd(const cv::Mat& a, cv::Point pa, const cv::Mat& b, cv::Point pb)
{
	cv::Mat wa, wb;
	a(cv::Rect(pa.x - 5, pa.y - 5, 11, 11)).convertTo(wa, CV_64F);
	b(cv::Rect(pb.x - 5, pb.y - 5, 11, 11)).convertTo(wb, CV_64F);
	cv::Scalar ma, sa, mb, sb;
	cv::meanStdDev(wa, ma, sa);
	cv::meanStdDev(wb, mb, sb);
	if (sa[0] < 10 || sb[0] < 10) return 1e9;  // textureless (only image noise): not checkable
	cv::Mat d = (wa - ma[0]) / sa[0] - (wb - mb[0]) / sb[0];
	return d.dot(d) / d.total();
}
}  // namespace

TEST(SimApp, SnapshotLandmarksAppearWhereTruthSaysInBothImages)
{
	const std::string dir = tempDir("snap");
	SimApp app;
	runApp(
	    {"--world", kLab, "--snapshot", "--pose", "0.5,0,0", "--head", "55,20,-2,2", "--out", dir},
	    app);
	const auto truth = nlohmann::json::parse(std::ifstream(dir + "/truth.json"));
	const cv::Mat L = cv::imread(dir + "/left.png", cv::IMREAD_GRAYSCALE);
	const cv::Mat R = cv::imread(dir + "/right.png", cv::IMREAD_GRAYSCALE);
	ASSERT_EQ(L.cols, 640);
	int checked = 0;
	for (const auto& l : truth["landmarks"])
	{
		const cv::Point pl(int(std::lround(double(l["left_px"][0]))),
		                   int(std::lround(double(l["left_px"][1]))));
		const cv::Point pr(int(std::lround(double(l["right_px"][0]))),
		                   int(std::lround(double(l["right_px"][1]))));
		if (pl.x < 6 || pl.y < 6 || pl.x > 633 || pl.y > 473 || pr.x < 6 || pr.y < 6 ||
		    pr.x > 633 || pr.y > 473)
			continue;
		const double d = nssd(L, pl, R, pr);
		if (d > 1e8) continue;
		EXPECT_LT(d, 0.3) << l["name"];  // the same surface point in both images
		++checked;
	}
	EXPECT_GE(truth["landmarks"].size(), 2u);
	EXPECT_GE(checked, 1);  // checker_left's centre is a checker corner: always textured
}

TEST(SimApp, SnapshotObjectsAreInFrontOfTheCameraAtTheirDepth)
{
	const std::string dir = tempDir("table");
	SimApp app;
	runApp({"--world", kLab, "--snapshot", "--pose", "0,0,0", "--head", "0,-14,-4,4", "--out", dir},
	       app);
	const auto truth = nlohmann::json::parse(std::ifstream(dir + "/truth.json"));
	const cv::Mat depth = cv::imread(dir + "/depth_left_mm.png", cv::IMREAD_UNCHANGED);
	ASSERT_EQ(depth.type(), CV_16UC1);
	ASSERT_GE(truth["objects"].size(), 4u);
	int unoccluded = 0;
	for (const auto& o : truth["objects"])
	{
		const double z_mm = 1000 * double(o["T_OinL"][2][3]);
		const int u = int(std::lround(double(o["left_px_of_origin"][0])));
		const int v = int(std::lround(double(o["left_px_of_origin"][1])));
		// O's origin is the centre of the footprint: the surface seen there is the object's front,
		// at most its radius (< 100 mm) nearer than the origin, never behind the table top
		const double d_mm = depth.at<uint16_t>(v, u);
		EXPECT_LT(d_mm, z_mm + 15) << o["name"];
		if (o["origin_occluded"]) continue;  // another object stands in front of it
		EXPECT_GT(d_mm, z_mm - 120) << o["name"];
		++unoccluded;
	}
	EXPECT_GE(unoccluded, 3);
}

TEST(SimApp, ShortRecordingReadsBack)
{
	const std::string path = tempDir("rec") + "/run.rawlog";
	SimApp app;
	runApp({"--world", kLab, "--out", path, "--max-steps", "3", "--json"}, app);
	const auto recs = mrolr::io::readRawlog(path);
	ASSERT_EQ(recs.size(), 4u);                   // the start plus 3 steps
	ASSERT_TRUE(recs[0].true_zxphi.has_value());
	EXPECT_LT(recs[0].true_zxphi->norm(), 1e-12);  // starts at W0
	EXPECT_EQ(app.frames_written, 4);
	EXPECT_TRUE(recs.back().has_stereo);
	EXPECT_GT(recs.back().odometry_zxphi.norm() + std::abs(double(recs.back().ticks_left)), 0);
	EXPECT_GT(app.render_s, 0);
	EXPECT_LE(app.render_s, app.total_s);
}

TEST(SimApp, BadArgumentsAreUsageErrors)
{
	SimApp app;
	EXPECT_THROW(app.initialize({"mrolr-sim", "--snapshot", "--out", "x"}),
	             mrolr::util::UsageError);  // no --world
	EXPECT_THROW(
	    app.initialize({"mrolr-sim", "--world", kLab, "--snapshot", "--head", "1,2", "--out", "x"}),
	    mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"mrolr-sim", "--world", kLab, "--snapshot", "--scene3d", "a"}),
	             mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"mrolr-sim", "--world", kLab, "--bogus"}),
	             mrolr::util::UsageError);
}
