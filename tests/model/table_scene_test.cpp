// Scene model of the lab table from one rendered stereo pair (issue 6, thesis 4.3, 7.1): the
// simulator renders maps/lab with the table about 1 m ahead, stereo::reconstructScene builds the
// wire-frame, and model::compareToTruth measures it against the exact wire-frame of the table top
// and its objects, clipped to what the left camera sees (model::visibleWireFrame on the rendered
// depth, and to what BOTH cameras see with the right camera's depth too: a stereo pair cannot
// reconstruct an edge only one camera sees).
//
// The claims are over the eight table views of docs/model.md (scripts/scene-breakdown.py), not one
// view: what the shipped pipeline recovers of the set, how accurately, and that each step of
// docs/model.md adds length over the set without adding false features.
#include <mrolr/geometry/Frames.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/VisibleTruth.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/SceneWireFrame.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFile.h>

#include <gtest/gtest.h>
#include <opencv2/core/eigen.hpp>

#include <algorithm>
#include <iostream>
#include <numeric>

using namespace mrolr;

namespace
{
const std::string kDir = MROLR_SOURCE_DIR;

struct TableView
{
	stereo::StereoCalibration calib;
	cv::Mat left, right, depth_mm, depth_right_mm;
	model::WireFrame truth_L;        ///< exact objects' wire-frame, left camera, not clipped
	model::WireFrame with_tables_L;  ///< the same and the table tops' edges
	Eigen::Vector3d up_L = Eigen::Vector3d::UnitY();  ///< C0's up (+y) in the left camera
};

cv::Mat toMat(const mrpt::img::CImage& img)
{
	return img.asCvMatRef().clone();
}

/** The lab rendered from vehicle pose (z, x, phi_deg) with head angles in degrees. */
TableView renderTable(double z_m, double x_m, double phi_deg, std::array<double, 4> head_deg)
{
	const auto w = world::World::load(kDir + "/maps/lab/world.ini");
	const geometry::BiSightHead head(
	    geometry::BiSightOptions::fromFile(kDir + "/config/bisight.ini"));
	const auto lab = sim::buildLabScene(w);
	sim::RenderOptions ro;
	ro.loadFromConfigFile(mrpt::config::CConfigFile(kDir + "/config/sim.ini"), "render");
	sim::StereoRenderer renderer(head, ro);
	const double d = M_PI / 180;
	const geometry::HeadAngles a{head_deg[0] * d, head_deg[1] * d, head_deg[2] * d,
	                             head_deg[3] * d};
	const auto f = renderer.render(
	    *lab.scene, geometry::T_C0inW({z_m, x_m, phi_deg * d}, head.options().head_height_m), a);
	TableView v;
	v.calib = stereo::calibrationFromHead(head, a);
	v.up_L = head.T_LinC0(a).linear().transpose() * Eigen::Vector3d::UnitY();
	v.left = toMat(f.left);
	v.right = toMat(f.right);
	cv::eigen2cv(Eigen::MatrixXf(f.depth_left_m.asEigen() * 1000.0f), v.depth_mm);
	cv::eigen2cv(Eigen::MatrixXf(f.depth_right_m.asEigen() * 1000.0f), v.depth_right_mm);
	v.truth_L = sim::tableSceneInCamera(w, lab.shapes, f.T_LinW, sim::SceneParts::Objects);
	v.with_tables_L =
	    sim::tableSceneInCamera(w, lab.shapes, f.T_LinW, sim::SceneParts::ObjectsAndTables);
	return v;
}

/** Quality of the scene model against the truth seen by the left camera (both = false) or by
 * both cameras; with @p up the reconstruction knows the up direction (as with --head). */
model::ModelQuality measure(const TableView& v, const model::WireFrame& truth_L,
                            const stereo::SceneOptions& o, bool both = false, bool up = false)
{
	const auto scene = model::sceneToWireFrame(stereo::reconstructScene(
	    v.left, v.right, v.calib, o, up ? std::optional(v.up_L) : std::nullopt));
	const auto visible =
	    both ? model::visibleInBothCameras(truth_L, v.depth_mm, v.depth_right_mm, v.calib)
	         : model::visibleWireFrame(truth_L, v.depth_mm, v.calib);
	const auto q = model::compareToTruth(scene, visible);
	std::cout << (both ? "seen by both cameras " : "seen by the left camera ") << q.true_length_mm
	          << " mm of " << model::totalLength(truth_L) << " mm\n";
	model::printQuality(q, std::cout);
	return q;
}

stereo::SceneOptions shippedOptions()
{
	stereo::SceneOptions o;
	o.loadFromConfigFile(mrpt::config::CConfigFile(kDir + "/config/model.ini"), "scene");
	return o;
}
}  // namespace

TEST(TableScene, VisibleTruthIsClippedByTheDepthImage)
{
	const auto v = renderTable(0.45, 0, 0, {0, -20, -8, 8});
	const auto objects = model::visibleWireFrame(v.truth_L, v.depth_mm, v.calib);
	const auto all = model::visibleWireFrame(v.with_tables_L, v.depth_mm, v.calib);
	const double seen = model::totalLength(objects);
	// the objects' far sides and bottoms are hidden, the table's near edges are in view
	EXPECT_GT(seen, 0.2 * model::totalLength(v.truth_L));
	EXPECT_LT(seen, 0.8 * model::totalLength(v.truth_L));
	EXPECT_GT(model::totalLength(all), seen + 1000);
	for (const auto& c : objects.conics) EXPECT_LE(c.t2 - c.t1, 2 * M_PI + 1e-9);
	EXPECT_THROW(model::visibleWireFrame(v.truth_L, cv::Mat(10, 10, CV_16U), v.calib),
	             std::invalid_argument);
}

TEST(TableScene, BothCameraTruthIsTheLeftTruthSeenByTheRightCameraToo)
{
	// view 2 of docs/model.md: the drink package at the left image's border is outside the right
	// image, so the both-camera truth loses it
	const auto v = renderTable(0.35, 0.1, 5, {5, -22, -8, 8});
	const auto left = model::visibleWireFrame(v.truth_L, v.depth_mm, v.calib);
	const auto both = model::visibleInBothCameras(v.truth_L, v.depth_mm, v.depth_right_mm, v.calib);
	const double l = model::totalLength(left), b = model::totalLength(both);
	EXPECT_LT(b, l - 300);
	EXPECT_GT(b, 0.4 * l);
	// every both-camera piece lies on a left-camera piece
	for (const auto& s : model::sampleWireFrame(both, 2.0))
		EXPECT_LT(model::distanceToWireFrame(s.p, left), 1.0);
	// the same depth image on both sides is not the right camera's view: it is refused only for
	// its size, so check the size error names the right image
	try
	{
		model::visibleInBothCameras(v.truth_L, v.depth_mm, cv::Mat(10, 10, CV_16U), v.calib);
		ADD_FAILURE() << "a wrong right depth image was accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("right"), std::string::npos) << e.what();
	}
}

namespace
{
/** The eight table views of docs/model.md and scripts/scene-breakdown.py: vehicle (z m, x m,
 * phi deg) and head (pan, tilt, left vergence, right vergence deg), rendered once per process. */
const std::vector<TableView>& viewSet()
{
	struct Pose
	{
		double z_m, x_m, phi_deg;
		std::array<double, 4> head_deg;
	};
	static const std::vector<Pose> poses = {
	    {0.45, 0, 0, {0, -20, -8, 8}},     {0.35, 0.1, 5, {5, -22, -8, 8}},
	    {0.5, -0.2, -10, {0, -18, -7, 7}}, {0.4, 0.05, 3, {0, -20, -8, 8}},
	    {0.45, -0.1, -5, {-5, -20, -8, 8}}, {0.3, 0, 0, {0, -24, -8, 8}},
	    {0.5, 0.15, 8, {3, -19, -7, 7}},    {0.4, -0.15, -3, {-3, -21, -8, 8}}};
	static const std::vector<TableView> views = [] {
		std::vector<TableView> out;
		for (const auto& p : poses) out.push_back(renderTable(p.z_m, p.x_m, p.phi_deg, p.head_deg));
		return out;
	}();
	return views;
}

double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}

/** ModelQuality pooled over the view set: lengths summed, errors pooled before the median. */
struct SetQuality
{
	double true_length_mm = 0, recovered_length_mm = 0;
	int model_features = 0, false_features = 0;
	std::vector<double> endpoint_errors_mm, conic_radius_errors_mm, fractions;

	double recoveredFraction() const { return recovered_length_mm / true_length_mm; }
	double falseShare() const { return double(false_features) / std::max(1, model_features); }
};

/** Every view of the set reconstructed with @p o, measured against what both cameras see;
 * @p up: the reconstruction knows the up direction, as the head's views do (--head). */
SetQuality measureSet(const stereo::SceneOptions& o, bool up)
{
	SetQuality s;
	for (const auto& v : viewSet())
	{
		const auto q = measure(v, v.truth_L, o, true, up);
		s.true_length_mm += q.true_length_mm;
		s.recovered_length_mm += q.recovered_length_mm;
		s.model_features += q.model_features;
		s.false_features += q.false_features;
		s.fractions.push_back(q.recovered_fraction);
		s.endpoint_errors_mm.insert(s.endpoint_errors_mm.end(), q.endpoint_errors_mm.begin(),
		                            q.endpoint_errors_mm.end());
		s.conic_radius_errors_mm.insert(s.conic_radius_errors_mm.end(),
		                                q.conic_radius_errors_mm.begin(),
		                                q.conic_radius_errors_mm.end());
	}
	std::printf("set of %zu views: %.1f %% of %.0f mm (worst view %.1f %%), false %d of %d, "
	            "median endpoint %.2f mm, median conic radius %.2f mm\n",
	            viewSet().size(), 100 * s.recoveredFraction(), s.true_length_mm,
	            100 * *std::min_element(s.fractions.begin(), s.fractions.end()), s.false_features,
	            s.model_features, median(s.endpoint_errors_mm), median(s.conic_radius_errors_mm));
	return s;
}

/** A step of docs/model.md "adds what it is for" over the set: at least @p min_gain of the set's
 * visible length more, and what it adds is not mostly false: the false share of the features
 * rises by at most 5 points. */
void expectStepGains(const SetQuality& without, const SetQuality& with, double min_gain)
{
	EXPECT_GE(with.recoveredFraction(), without.recoveredFraction() + min_gain);
	EXPECT_LE(with.falseShare(), without.falseShare() + 0.05);
}
}  // namespace

// The shipped pipeline, as the head reconstructs (with the up direction): over the set, at least
// 45 % of the edge length both cameras see is recovered (measured 50.3 %, docs/model.md), with millimetre line ends and rims within
// 10 mm of their radius, and no view is left under 30 % (docs/model.md, the 8-view
// table). False features are real image edges that are not object features (silhouettes, the
// table's edges, the letters); they stay under two thirds of what is reconstructed.
TEST(TableScene, ShippedPipelineOverTheViewSet)
{
	const auto s = measureSet(shippedOptions(), true);
	EXPECT_GE(s.recoveredFraction(), 0.45);
	EXPECT_GE(*std::min_element(s.fractions.begin(), s.fractions.end()), 0.30);
	EXPECT_LT(median(s.endpoint_errors_mm), 3.0);
	EXPECT_LT(median(s.conic_radius_errors_mm), 10.0);
	EXPECT_LT(s.falseShare(), 2.0 / 3.0);
}

// Step 4 (piece stereo) over the set: strings alone miss the box edges whose corners are not
// matched as strings.
TEST(TableScene, PieceStereoAddsLengthOverTheViewSet)
{
	auto strings_only = shippedOptions();
	strings_only.segments.enabled = false;
	expectStepGains(measureSet(strings_only, true), measureSet(shippedOptions(), true), 0.10);
}

// Full-image rectification (alpha 1, 1.25 x the size) keeps the objects at the image borders that
// alpha 0 crops away.
TEST(TableScene, FullImageRectificationAddsLengthOverTheViewSet)
{
	auto cropped = shippedOptions();
	cropped.rectify = stereo::RectifyOptions{};  // alpha 0, same size
	expectStepGains(measureSet(cropped, true), measureSet(shippedOptions(), true), 0.01);
}

// Receding edges turn between the rectified views by their disparity gradient
// (dx_R/dy = dx_L/dy - dd/dy), by more than 10° and on some views more than 30°: the shipped
// wide limit matches them, a narrow one loses them.
TEST(TableScene, WideAngleLimitMatchesRecedingEdgesOverTheViewSet)
{
	const auto shipped = measureSet(shippedOptions(), true);
	for (const double narrow_deg : {10.0, 30.0})
	{
		auto narrow = shippedOptions();
		ASSERT_GT(shipped.recoveredFraction(), 0);
		ASSERT_LT(narrow_deg, narrow.segments.max_angle_diff_deg);
		narrow.segments.max_angle_diff_deg = narrow_deg;
		SCOPED_TRACE(narrow_deg);
		expectStepGains(measureSet(narrow, true), shipped, narrow_deg < 20 ? 0.02 : 0.005);
	}
}

// Step 9: with the up direction, rims are found as horizontal circles; with its key off, knowing
// the up direction changes nothing.
TEST(TableScene, HorizontalCirclesAddLengthOverTheViewSet)
{
	auto o = shippedOptions();
	ASSERT_TRUE(o.circles.enabled);
	o.edge_on_rims.enabled = false;  // step 9 alone (step 10 below)
	auto off = o;
	off.circles.enabled = false;
	const auto off_with_up = measureSet(off, true);
	expectStepGains(off_with_up, measureSet(o, true), 0.005);
	EXPECT_NEAR(off_with_up.recoveredFraction(), measureSet(o, false).recoveredFraction(), 1e-9);
}

// Step 10: rims seen edge-on between a cylinder's silhouettes (the bottle's shoulder and neck).
TEST(TableScene, EdgeOnRimsAddLengthOverTheViewSet)
{
	const auto o = shippedOptions();
	ASSERT_TRUE(o.edge_on_rims.enabled);
	auto off = o;
	off.edge_on_rims.enabled = false;
	const auto without = measureSet(off, true);
	const auto with = measureSet(o, true);
	expectStepGains(without, with, 0.005);
	EXPECT_LT(median(with.conic_radius_errors_mm), 10.0);
}
