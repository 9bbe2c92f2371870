// Integration of turntable views (thesis 6.1, B.2.1) on synthetic views in frame O: silhouettes of
// round bodies dropped, fixed edges kept (TurntableBuilderSupport), circles fitted to the arcs of
// several views (TurntableBuilderRims).
#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/TurntableBuilderRims.h>
#include <mrolr/model/TurntableBuilderSupport.h>
#include <mrolr/model/TurntableRimChords.h>
#include <mrolr/model/TurntableRimImages.h>
#include <mrolr/model/WireFrameSampling.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <sstream>

using namespace mrolr::model;

namespace
{
constexpr double kR = 35;  // mm, cylinder radius

Eigen::Vector3d onCylinder(double azimuth_deg, double z, double r = kR)
{
	const double a = azimuth_deg * M_PI / 180;
	return {r * std::cos(a), r * std::sin(a), z};
}

/** Turntable view at angle k·45°: the camera looks from O's azimuth −k·45° (frame O turns). */
double cameraAzimuthDeg(int k)
{
	return -45.0 * k;
}

/** View k of an upright cylinder: its two contour generators (at ±(90° + 3°) from the camera's
 * azimuth) and a fixed vertical seam at azimuth 22.5° when the seam faces the camera. */
WireFrame cylinderView(int k)
{
	WireFrame v;
	v.frame = WireFrameFrame::Object;
	const double cam = cameraAzimuthDeg(k);
	for (double side : {-93.0, 93.0})
		v.lines.push_back({0, onCylinder(cam + side, 5), onCylinder(cam + side, 110)});
	if (std::cos((cam - 22.5) * M_PI / 180) > 0.5)
		v.lines.push_back({0, onCylinder(22.5, 5), onCylinder(22.5, 110)});
	return v;
}

std::vector<double> angles(size_t n)
{
	std::vector<double> a;
	for (size_t k = 0; k < n; ++k) a.push_back(45.0 * k);
	return a;
}

Conic3 circleArc(const Eigen::Vector3d& c, double r, double t1, double t2)
{
	return {0, c, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), r, r, t1, t2};
}
}  // namespace

TEST(TurntableSupport, SilhouettesOfACylinderGoAndAFixedSeamStays)
{
	std::vector<WireFrame> views;
	for (int k = 0; k < 8; ++k) views.push_back(cylinderView(k));
	ViewSupportOptions o;
	const size_t removed = keepFeaturesSeenFromNearViews(views, angles(8), o);
	EXPECT_EQ(removed, 16u);  // both contours of every view
	size_t seams = 0;
	for (const auto& v : views)
		for (const auto& l : v.lines)
		{
			EXPECT_LT((l.p1 - onCylinder(22.5, 5)).norm(), 1e-9) << "a contour generator survived";
			++seams;
		}
	EXPECT_EQ(seams, 2u);  // views 0 and 7 see the seam
	// every view counts (no silhouette rule): the contours agree with the opposite views'
	std::vector<WireFrame> all;
	for (int k = 0; k < 8; ++k) all.push_back(cylinderView(k));
	o.max_view_angle_deg = 180;
	EXPECT_EQ(keepFeaturesSeenFromNearViews(all, angles(8), o), 0u);
}

TEST(TurntableSupport, EdgeAcrossTheViewSeenOnlyFromOppositeSidesStays)
{
	// a horizontal top edge lies along the scanlines of the views across it: seen from 0° and 180°
	std::vector<WireFrame> views(8);
	const Line3 edge{0, {-40, 20, 60}, {40, 20, 60}};
	views[0].lines.push_back(edge);
	views[4].lines.push_back(edge);
	EXPECT_EQ(keepFeaturesSeenFromNearViews(views, angles(8), ViewSupportOptions()), 0u);
	// the same seen once only goes
	views[4].lines.clear();
	EXPECT_EQ(keepFeaturesSeenFromNearViews(views, angles(8), ViewSupportOptions()), 1u);
}

TEST(TurntableSupport, SteepEdgeFromOppositeViewsNeedsAnEdgeInANearImage)
{
	// a box corner seen in views 0 and 4 only: kept when view 1's left image shows it
	const Line3 corner{0, {30, 20, 5}, {30, 20, 100}};
	auto twoViews = [&]
	{
		std::vector<WireFrame> v(8);
		v[0].lines.push_back(corner);
		v[4].lines.push_back(corner);
		return v;
	};
	std::vector<ViewEdges> edges(8);
	for (auto& e : edges)
	{
		e.gradient = cv::Mat::zeros(480, 640, CV_32F);
		e.K = cv::Matx33d(700, 0, 320, 0, 700, 240, 0, 0, 1);
		e.T_OinL = Eigen::Translation3d(-30, 0, 600) *
		           Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX());
	}
	auto views = twoViews();
	EXPECT_EQ(keepFeaturesSeenFromNearViews(views, angles(8), ViewSupportOptions(), edges), 2u);
	std::vector<cv::Point3d> ends;
	for (const auto* p : {&corner.p1, &corner.p2})
	{
		const Eigen::Vector3d q = edges[1].T_OinL * *p;
		ends.emplace_back(-q.x(), -q.y(), q.z());
	}
	std::vector<cv::Point2d> px;
	cv::projectPoints(ends, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), edges[1].K, edges[1].D, px);
	cv::line(edges[1].gradient, px[0], px[1], cv::Scalar(40), 1);
	views = twoViews();
	EXPECT_EQ(keepFeaturesSeenFromNearViews(views, angles(8), ViewSupportOptions(), edges), 1u);
	EXPECT_EQ(views[0].lines.size(), 1u);  // view 1 (near view 0) shows the edge
	EXPECT_TRUE(views[4].lines.empty());   // views 2, 3, 5, 6 (near view 4) do not
	EXPECT_GT(imageEdgeShare(sampleLine(corner, 2, 0), edges[1], 8), 0.9);
}

TEST(TurntableRims, ArcsOfFourViewsGiveOneCircleAndNestedRimsStaySeparate)
{
	const Eigen::Vector3d c(6, -4, 115);  // off the turntable axis: no centre is assumed
	std::vector<WireFrame> views(4);
	for (int k = 0; k < 4; ++k)
	{
		const double t = k * M_PI / 2 + 0.05 * k;
		views[k].conics.push_back(circleArc(c, 33 + 0.2 * (k % 2), t - 0.9, t + 0.9));
		views[k].conics.push_back(circleArc(c + Eigen::Vector3d(0, 0, 5), 28, t - 0.8, t + 0.8));
		views[k].lines.push_back({0, {-60, 50, 40}, {-60, 50, 90}});  // not on any circle
	}
	const auto rims = fitRimsAcrossViews(views, RimOptions());
	ASSERT_EQ(rims.size(), 2u);
	for (const auto& rim : rims)
	{
		const bool outer = rim.a > 30.5;
		EXPECT_NEAR(rim.a, outer ? 33.1 : 28, 0.3);
		EXPECT_NEAR(rim.a, rim.b, 1e-9);
		EXPECT_LT((rim.centre - c - Eigen::Vector3d(0, 0, outer ? 0 : 5)).norm(), 0.3);
		EXPECT_GT(std::abs(rim.normal.z()), 0.999);
		EXPECT_GT(rim.t2 - rim.t1, 1.9 * M_PI);  // four arcs of ~100° around the circle
	}
	for (const auto& v : views)
	{
		EXPECT_TRUE(v.conics.empty()) << "single-view arcs on a rim are replaced by it";
		EXPECT_EQ(v.lines.size(), 1u);
	}
}

TEST(TurntableRims, NoCircleFromOneViewOrFromStraightEdges)
{
	std::vector<WireFrame> one(2);
	one[0].conics.push_back(circleArc({0, 0, 50}, 30, 0, 5));
	EXPECT_TRUE(fitRimsAcrossViews(one, RimOptions()).empty());
	EXPECT_EQ(one[0].conics.size(), 1u);
	// a square's four edges touch its inscribed circle, but no arc supports a circle
	std::vector<WireFrame> square(4);
	for (auto& v : square)
		for (int s = 0; s < 4; ++s)
		{
			const Eigen::Rotation2Dd R(s * M_PI / 2);
			const Eigen::Vector2d a = R * Eigen::Vector2d(30, -30), b = R * Eigen::Vector2d(30, 30);
			v.lines.push_back({0, {a.x(), a.y(), 60}, {b.x(), b.y(), 60}});
		}
	EXPECT_TRUE(fitRimsAcrossViews(square, RimOptions()).empty());
}

TEST(TurntableOptions, KeysAreReadDumpedAndCheckedByName)
{
	mrpt::config::CConfigFileMemory cfg(
	    "[turntable]\nsupport_tol_mm = 3\nrim_tol_mm = 0.8\nrim_min_views = 4\n");
	ViewSupportOptions s;
	RimOptions r;
	s.loadFromConfigFile(cfg, "turntable");
	r.loadFromConfigFile(cfg, "turntable");
	EXPECT_EQ(s.tol_mm, 3);
	EXPECT_EQ(r.tol_mm, 0.8);
	EXPECT_EQ(r.min_views, 4);
	std::ostringstream out;
	s.dump(out);
	r.dump(out);
	EXPECT_NE(out.str().find("support_tol_mm = 3"), std::string::npos) << out.str();
	EXPECT_NE(out.str().find("rim_min_views = 4"), std::string::npos) << out.str();
	for (const std::string bad : {"support_min_fraction = 2", "rim_consume_fraction = -1"})
	{
		mrpt::config::CConfigFileMemory b("[turntable]\n" + bad + "\n");
		const std::string key = bad.substr(0, bad.find(' '));
		try
		{
			ViewSupportOptions().loadFromConfigFile(b, "turntable");
			RimOptions().loadFromConfigFile(b, "turntable");
			ADD_FAILURE() << bad;
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
		}
	}
}

namespace
{
/** A left camera at @p C (frame O, mm) looking at @p target, thesis axes (x left, y up). */
ViewEdges cameraAt(const Eigen::Vector3d& C, const Eigen::Vector3d& target)
{
	ViewEdges e;
	e.gradient = cv::Mat::zeros(480, 640, CV_32F);
	e.K = cv::Matx33d(700, 0, 320, 0, 700, 240, 0, 0, 1);
	const Eigen::Vector3d z = (target - C).normalized();
	const Eigen::Vector3d y =
	    (Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(z) * z).normalized();
	Eigen::Isometry3d T_LinO = Eigen::Isometry3d::Identity();
	T_LinO.linear() << y.cross(z), y, z;
	T_LinO.translation() = C;
	e.T_OinL = T_LinO.inverse();
	return e;
}

/** Draws the part t1..t2 of conic @p c into @p e's gradient map as an edge of 40 grey levels/px. */
void drawArc(ViewEdges& e, const Conic3& c, double t1, double t2)
{
	std::vector<cv::Point3d> p;
	for (double t = t1; t <= t2 + 1e-9; t += 0.02)
	{
		const Eigen::Vector3d q = e.T_OinL * c.pointAt(t);
		p.emplace_back(-q.x(), -q.y(), q.z());
	}
	std::vector<cv::Point2d> px;
	cv::projectPoints(p, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), e.K, e.D, px);
	for (size_t i = 1; i < px.size(); ++i)
		cv::line(e.gradient, px[i - 1], px[i], cv::Scalar(40), 1);
}
}  // namespace

TEST(TurntableRims, HorizontalRimIsCompletedWhereAViewFacingItShowsAnEdge)
{
	// a rim found in 3D on its y >= 0 half (t in 0..π); a camera on the -y side faces the rest
	const Conic3 half = circleArc({0, 0, 150}, kR, 0, M_PI);
	std::vector<ViewEdges> edges = {cameraAt({0, -600, 400}, {0, 0, 150}),
	                                cameraAt({0, 600, 400}, {0, 0, 150})};
	RimImageOptions o;
	o.min_gradient = 8;
	std::vector<Conic3> rims = {half};
	EXPECT_EQ(completeRimsFromImages(rims, edges, o), 0);  // no image edge: the arc stays
	EXPECT_NEAR(rims[0].t2 - rims[0].t1, M_PI, 1e-9);
	// the far camera (+y) does not face the missing half: an edge drawn there in its image does
	// not count
	drawArc(edges[1], half, M_PI, 2 * M_PI);
	EXPECT_EQ(completeRimsFromImages(rims, edges, o), 0);
	drawArc(edges[0], half, M_PI, 2 * M_PI);
	// the camera faces the middle 120° of the missing half (radial direction within 72° of it)
	EXPECT_GE(completeRimsFromImages(rims, edges, o), 12);
	EXPECT_GT(rims[0].t2 - rims[0].t1, 1.8 * M_PI);
	WireFrame completed;
	completed.conics = rims;
	for (double t = 0.1; t < M_PI; t += 0.3)  // the same circle, its arc kept and extended
		EXPECT_LT(distanceToWireFrame(half.pointAt(t), completed), 0.5) << t;
	EXPECT_LT(distanceToWireFrame(half.pointAt(1.5 * M_PI), completed), 0.5);
	// off (gradient 0), and a circle in a vertical plane (a handle), are left as they are
	std::vector<Conic3> again = {half};
	EXPECT_EQ(completeRimsFromImages(again, edges, RimImageOptions{}), 0);
	Conic3 handle = half;
	handle.normal = Eigen::Vector3d::UnitX();
	handle.major = Eigen::Vector3d::UnitY();
	std::vector<Conic3> vertical = {handle};
	EXPECT_EQ(completeRimsFromImages(vertical, edges, o), 0);
}

namespace
{
/** [turntable] with the single line @p line is rejected by TurntableOptions, naming its key. */
void expectTurntableKeyRejected(const std::string& line)
{
	mrpt::config::CConfigFileMemory bad("[turntable]\n" + line + "\n");
	const std::string key = line.substr(0, line.find(' '));
	try
	{
		TurntableOptions().loadFromConfigFile(bad, "turntable");
		ADD_FAILURE() << line << " accepted";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
	}
}
}  // namespace

TEST(TurntableOptions, RimImageKeysAreReadAndChecked)
{
	mrpt::config::CConfigFileMemory cfg(
	    "[turntable]\nrim_image_gradient = 12\nrim_image_min_fraction = 0.6\n");
	TurntableOptions t;
	t.loadFromConfigFile(cfg, "turntable");
	EXPECT_EQ(t.rim_images.min_gradient, 12);
	EXPECT_EQ(t.rim_images.min_fraction, 0.6);
	expectTurntableKeyRejected("rim_image_min_fraction = 1.5");
}

TEST(TurntableRims, HorizontalRimFromShortChordsOfThreeViewsIsFoundInTheImages)
{
	// a rim r 14 at z 190 that each view reconstructs only as a short straight chord across its
	// front (cut short on one side), and whose images show the circle's front half as an edge
	const Conic3 truth = circleArc({0, 0, 190}, 14, 0, 2 * M_PI);
	std::vector<WireFrame> views;
	std::vector<ViewEdges> edges;
	for (int k = 0; k < 4; ++k)
	{
		const double az = k * M_PI / 2;  // camera azimuth in O
		const Eigen::Vector2d d(std::cos(az), std::sin(az)), e(-d.y(), d.x());
		edges.push_back(cameraAt({600 * d.x(), 600 * d.y(), 450}, {0, 0, 190}));
		drawArc(edges.back(), truth, az - M_PI / 2, az + M_PI / 2);
		WireFrame v;
		v.frame = WireFrameFrame::Object;
		const Eigen::Vector2d front = 5 * d;
		v.lines.push_back({0,
		                   {front.x() - 10 * e.x(), front.y() - 10 * e.y(), 189},
		                   {front.x() + 5 * e.x(), front.y() + 5 * e.y(), 189.3}});
		v.lines.push_back({0, {30, 0, 20}, {30, 0, 120}});  // an unrelated steep edge stays
		views.push_back(v);
	}
	RimImageOptions io;
	io.min_gradient = 8;
	RimChordOptions o;
	auto found = views;
	const auto rims = rimsFromChords(found, edges, {}, o, io);
	ASSERT_EQ(rims.size(), 1u);
	EXPECT_NEAR(rims[0].a, 14, 1.0);
	EXPECT_NEAR(rims[0].centre.z(), 190, 1.0);
	EXPECT_LT(rims[0].centre.head<2>().norm(), 1.5);
	EXPECT_GE(rims[0].t2 - rims[0].t1, M_PI);

	// a horizontal rim already found at that height, chords of two views only, no image edges, or
	// the key at 0: no rim
	auto again = views;
	EXPECT_TRUE(rimsFromChords(again, edges, {truth}, o, io).empty());
	auto two = std::vector<WireFrame>(views.begin(), views.begin() + 2);
	auto two_edges = std::vector<ViewEdges>(edges.begin(), edges.begin() + 2);
	EXPECT_TRUE(rimsFromChords(two, two_edges, {}, o, io).empty());
	std::vector<ViewEdges> blank;
	for (const auto& v : edges)
	{
		ViewEdges b = v;
		b.gradient = cv::Mat::zeros(v.gradient.size(), CV_32F);
		blank.push_back(b);
	}
	auto dark = views;
	EXPECT_TRUE(rimsFromChords(dark, blank, {}, o, io).empty());
	RimChordOptions off;
	off.min_views = 0;
	EXPECT_TRUE(rimsFromChords(views, edges, {}, off, io).empty());
	// a box's chords (the span across the view changes with the view) give no rim
	auto box = views;
	box[1].lines[0].p2 += 12 * (box[1].lines[0].p2 - box[1].lines[0].p1).normalized();
	EXPECT_TRUE(rimsFromChords(box, edges, {}, o, io).empty());
}

TEST(TurntableOptions, RimChordKeysAreReadAndChecked)
{
	mrpt::config::CConfigFileMemory cfg(
	    "[turntable]\nrim_chord_min_views = 4\nrim_chord_min_image_arc_deg = 150\n");
	TurntableOptions t;
	t.loadFromConfigFile(cfg, "turntable");
	EXPECT_EQ(t.rim_chords.min_views, 4);
	EXPECT_EQ(t.rim_chords.min_image_arc_deg, 150);
	expectTurntableKeyRejected("rim_chord_max_radius_ratio = 0.5");
}

TEST(TurntableOptions, ViewsAreReconstructedWithoutCornerPlacedSegments)
{
	// corner-placed segments would turn a rim's edge-on chords into lines (docs/model.md, step 7)
	mrolr::stereo::SceneOptions so;
	so.segments.corner_lines = true;
	so.segments.max_angle_diff_deg = 42;
	const auto t = turntableSceneOptions(so);
	EXPECT_FALSE(t.segments.corner_lines);
	EXPECT_EQ(t.segments.max_angle_diff_deg, 42);  // the rest as given
}
