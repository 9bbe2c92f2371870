// Scene model of the lab table from one rendered stereo pair (issue 6, thesis 4.3, 7.1): the
// simulator renders maps/lab with the table about 1 m ahead, stereo::reconstructScene builds the
// wire-frame, and model::compareToTruth measures it against the exact wire-frame of the table top
// and its objects, clipped to what the left camera sees (model::visibleWireFrame on the rendered
// depth, and to what BOTH cameras see with the right camera's depth too: a stereo pair cannot
// reconstruct an edge only one camera sees). Issue target: at least 60 % of the visible edge
// length recovered; not reached yet (docs/model.md): the test holds the levels measured and the
// gain of piece stereo.
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

#include <iostream>

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

TEST(TableScene, PieceStereoRecoversMoreOfTheObjectsAtOneMetre)
{
	const auto v = renderTable(0.45, 0, 0, {0, -20, -8, 8});
	auto strings_only = shippedOptions();
	strings_only.segments.enabled = false;
	const auto q0 = measure(v, v.truth_L, strings_only);
	const auto q = measure(v, v.truth_L, shippedOptions());
	EXPECT_GT(q.recovered_fraction, q0.recovered_fraction + 0.05);
	EXPECT_GE(q.recovered_fraction, 0.50);  // measured 0.524 (0.480 without corner-placed lines)
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
	EXPECT_LT(q.median_conic_radius_error_mm, 10.0);
	EXPECT_LE(q.false_features, 60);  // measured 54 (silhouettes, table edges)
	const auto qb = measure(v, v.truth_L, shippedOptions(), true);
	EXPECT_GE(qb.recovered_fraction, 0.60);         // issue 6's target; measured 0.630 (0.578 before)
	measure(v, v.with_tables_L, shippedOptions());  // reported: table tops' edges included
}

TEST(TableScene, FullImageRectificationKeepsMoreOfTheBorderObjects)
{
	// view 2 of docs/model.md: the large cup and the can stand at the left image's border, which
	// rectification with alpha = 0 crops away. Measured with the up direction, as the head's views
	// are reconstructed (mrolr-model scene --head): the border objects' rims are horizontal
	// circles there. On the luminance renders (e9796d9) without the up direction the gain is
	// 2.9 points and none of it on the border objects (large cup 176 -> 121 mm, docs/model.md)
	const auto v = renderTable(0.35, 0.1, 5, {5, -22, -8, 8});
	auto cropped = shippedOptions();
	cropped.rectify = stereo::RectifyOptions{};  // alpha 0, same size
	const auto full = shippedOptions();          // alpha 1, 1.25 x the image size
	const auto q0 = measure(v, v.truth_L, cropped, true, true);
	const auto q = measure(v, v.truth_L, full, true, true);
	EXPECT_GT(q.recovered_fraction, q0.recovered_fraction + 0.03);
	EXPECT_GE(q.recovered_fraction, 0.30);  // measured 0.446 (cropped: 0.307)
}

TEST(TableScene, RecedingEdgesTurnBetweenTheViewsAndAreStillMatched)
{
	// view 3 of docs/model.md: the box tops' receding edges turn between the rectified views by
	// their disparity gradient; a 10° limit on the direction difference lost them
	const auto v = renderTable(0.5, -0.2, -10, {0, -18, -7, 7});
	auto strict = shippedOptions();
	strict.segments.max_angle_diff_deg = 10;
	const auto q0 = measure(v, v.truth_L, strict, true);
	const auto q = measure(v, v.truth_L, shippedOptions(), true);
	EXPECT_GT(q.recovered_fraction, q0.recovered_fraction + 0.05);
	EXPECT_GE(q.recovered_fraction, 0.41);  // measured 0.452 (10°: 0.352)
	// measured 46 of 105 (10°: 33): the table's back edge and the letters on the bright cube are
	// matched too, and corner-placed lines add 5 (41 without; docs/model.md)
	EXPECT_LE(q.false_features, 50);
}

TEST(TableScene, SteepDisparityGradientsNeedTheWideAngleLimit)
{
	// view 5 of docs/model.md: receding edges of the box tops turn between the rectified views by
	// their disparity gradient (dx_R/dy = dx_L/dy - dd/dy) by more than 30°
	const auto v = renderTable(0.45, -0.1, -5, {-5, -20, -8, 8});
	auto narrow = shippedOptions();
	narrow.segments.max_angle_diff_deg = 30;
	const auto q0 = measure(v, v.truth_L, narrow, true);
	const auto q = measure(v, v.truth_L, shippedOptions(), true);
	EXPECT_GT(q.recovered_fraction, q0.recovered_fraction + 0.03);  // measured 0.427 (30°: 0.391)
	EXPECT_LE(q.false_features, q0.false_features + 3);             // measured 44 (30°: 44)
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
}

TEST(TableScene, HorizontalCirclesWithTheUpDirection)
{
	// view 6 of scripts/scene-breakdown.py: the large cup's top rim about 3 px from edge-on, the
	// can, the cup; measured 37.1 % -> 43.3 % of the both-camera truth, false 58 -> 59
	// (docs/model.md step 9; 31.7 -> 46.2 % before the luminance renders of e9796d9, whose more
	// contrasted rims the stereo finds more of without the circles)
	const auto v = renderTable(0.5, 0.15, 8, {3, -19, -7, 7});
	auto o = shippedOptions();
	ASSERT_TRUE(o.circles.enabled);
	o.edge_on_rims.enabled = false;  // step 9 alone (step 10: EdgeOnRimsWithTheUpDirection)
	const auto without = measure(v, v.truth_L, o, true, false);
	const auto with = measure(v, v.truth_L, o, true, true);
	EXPECT_GE(with.recovered_fraction, without.recovered_fraction + 0.05);
	EXPECT_GE(with.recovered_fraction, 0.42);
	EXPECT_LE(with.false_features, without.false_features + 3);
	auto off = o;
	off.circles.enabled = false;  // the key turns the step off even with the up direction
	EXPECT_NEAR(measure(v, v.truth_L, off, true, true).recovered_fraction,
	            without.recovered_fraction, 1e-9);
}

TEST(TableScene, EdgeOnRimsWithTheUpDirection)
{
	// the table view with the up direction, as mrolr-model scene --head reconstructs it: the
	// bottle's shoulder and neck rims are seen edge-on between its silhouettes (docs/model.md
	// step 10)
	const auto v = renderTable(0.45, 0, 0, {0, -20, -8, 8});
	const auto o = shippedOptions();
	ASSERT_TRUE(o.edge_on_rims.enabled);
	auto off = o;
	off.edge_on_rims.enabled = false;
	const auto without = measure(v, v.truth_L, off, true, true);
	const auto with = measure(v, v.truth_L, o, true, true);
	EXPECT_GE(with.recovered_fraction, without.recovered_fraction + 0.05);
	EXPECT_GE(with.recovered_fraction, 0.65);  // issue 6's target is 0.6
	EXPECT_LE(with.false_features, without.false_features + 1);
	EXPECT_LT(with.median_conic_radius_error_mm, 10.0);
}
