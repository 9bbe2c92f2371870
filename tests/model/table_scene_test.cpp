// Scene model of the lab table from one rendered stereo pair (issue 6, thesis 4.3, 7.1): the
// simulator renders maps/lab with the table about 1 m ahead, stereo::reconstructScene builds the
// wire-frame, and model::compareToTruth measures it against the exact wire-frame of the table top
// and its objects, clipped to what the left camera sees (model::visibleWireFrame on the rendered
// depth). Issue target: at least 60 % of the visible edge length recovered; not reached yet
// (docs/model.md): the test holds the level measured and the gain of piece stereo.
#include <mrolr/geometry/Frames.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/VisibleTruth.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/SceneWireFrame.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/stereo/HeadCalibration.h>

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
	cv::Mat left, right, depth_mm;
	model::WireFrame truth_L;        ///< exact objects' wire-frame, left camera, not clipped
	model::WireFrame with_tables_L;  ///< the same and the table tops' edges
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
	v.left = toMat(f.left);
	v.right = toMat(f.right);
	cv::eigen2cv(Eigen::MatrixXf(f.depth_left_m.asEigen() * 1000.0f), v.depth_mm);
	v.truth_L = sim::tableSceneInCamera(w, lab.shapes, f.T_LinW, sim::SceneParts::Objects);
	v.with_tables_L =
	    sim::tableSceneInCamera(w, lab.shapes, f.T_LinW, sim::SceneParts::ObjectsAndTables);
	return v;
}

model::ModelQuality measure(const TableView& v, const model::WireFrame& truth_L,
                            const stereo::SceneOptions& o)
{
	const auto scene =
	    model::sceneToWireFrame(stereo::reconstructScene(v.left, v.right, v.calib, o));
	const auto visible = model::visibleWireFrame(truth_L, v.depth_mm, v.calib);
	const auto q = model::compareToTruth(scene, visible);
	std::cout << "visible " << q.true_length_mm << " mm of " << model::totalLength(truth_L)
	          << " mm\n";
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

TEST(TableScene, PieceStereoRecoversMoreOfTheObjectsAtOneMetre)
{
	const auto v = renderTable(0.45, 0, 0, {0, -20, -8, 8});
	auto strings_only = shippedOptions();
	strings_only.segments.enabled = false;
	const auto q0 = measure(v, v.truth_L, strings_only);
	const auto q = measure(v, v.truth_L, shippedOptions());
	EXPECT_GT(q.recovered_fraction, q0.recovered_fraction + 0.05);
	EXPECT_GE(q.recovered_fraction, 0.4);  // measured 0.423; issue target 0.6 (not reached)
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
	EXPECT_LT(q.median_conic_radius_error_mm, 10.0);
	measure(v, v.with_tables_L, shippedOptions());  // reported: table tops' edges included
}
