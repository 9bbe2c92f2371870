// Limbs of bodies of revolution (Limbs.h) and their use in the verification in the images
// (ImageVerifier.h): coaxial circles are grouped into a body, its outline generators seen from a
// camera lie on the projected silhouette, and a drawn can scores high at its pose with them and
// clearly lower 10 mm away.
#include "synthetic_rig.h"
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/Limbs.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/recog/WireFrameBuilder.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/imgproc.hpp>

#include <random>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
using test::calibration;
using test::kBaseline_mm;
using test::pixel;

/** A frustum about O's z: radius r0 at z = 0, r1 at z = h. */
struct Frustum
{
	double r0, r1, h;
	mrolr::model::WireFrame wireFrame() const
	{
		WireFrameBuilder b("frustum");
		b.circle({0, 0, 0}, r0).circle({0, 0, h}, r1);
		return b.build();
	}
	Eigen::Vector3d at(double t, double z) const
	{
		const double r = r0 + (r1 - r0) * z / h;
		return {r * std::cos(t), r * std::sin(t), z};
	}
};

/** Pixels of the frustum's surface (dense grid of points) seen through @p T_OinL. */
std::vector<cv::Point2f> surfacePixels(const Frustum& f, const Eigen::Isometry3d& T_OinL,
                                       double cam_x_cv_mm)
{
	std::vector<cv::Point2f> px;
	for (int i = 0; i < 720; ++i)
		for (int k = 0; k <= 40; ++k)
			px.emplace_back(pixel(T_OinL * f.at(i * M_PI / 360, f.h * k / 40), cam_x_cv_mm));
	return px;
}

/** Distance (px) from @p p to the boundary of the convex polygon @p hull. */
double distanceToOutline(const std::vector<cv::Point2f>& hull, const cv::Point2d& p)
{
	return std::abs(cv::pointPolygonTest(hull, cv::Point2f(p), true));
}

Eigen::Isometry3d poseOf(double yaw, double tilt, const Eigen::Vector3d& t)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()) *
	              Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))
	                 .toRotationMatrix();
	T.translation() = t;
	return T;
}
}  // namespace

TEST(limbs, CoaxialCirclesMakeOneBodyAndBoxesNone)
{
	const auto can = revolutionBodiesOf(featuresOf(makeCan()));
	ASSERT_EQ(can.size(), 1u);
	EXPECT_GT(std::abs(can[0].axis_dir.z()), 0.999);
	ASSERT_FALSE(can[0].profile.empty());
	EXPECT_NEAR(can[0].profile.back().z1_mm - can[0].profile.front().z0_mm, 115, 1e-6);
	for (const auto& s : can[0].profile) EXPECT_NEAR(s.r0_mm + s.r1_mm, 66, 1e-6);
	EXPECT_TRUE(revolutionBodiesOf(featuresOf(makeStaplerBox())).empty());
	EXPECT_TRUE(revolutionBodiesOf(featuresOf(makeAlphabetCube())).empty());
	// a step (a lid of radius 28 on a body of radius 33): body and lid are separate frusta
	WireFrameBuilder lid("lidded");
	lid.circle({0, 0, 0}, 33).circle({0, 0, 115}, 33).circle({0, 0, 115}, 28).circle({0, 0, 120}, 28);
	const auto lidded = revolutionBodiesOf(featuresOf(lid.build()));
	ASSERT_EQ(lidded.size(), 1u);
	ASSERT_EQ(lidded[0].profile.size(), 2u);
	EXPECT_NEAR(lidded[0].profile[0].r0_mm, 33, 1e-6);
	EXPECT_NEAR(lidded[0].profile[0].r1_mm, 33, 1e-6);
	EXPECT_NEAR(lidded[0].profile[1].r0_mm, 28, 1e-6);
	EXPECT_NEAR(lidded[0].profile[1].r1_mm, 28, 1e-6);
	EXPECT_NEAR(lidded[0].profile[1].z1_mm - lidded[0].profile[1].z0_mm, 5, 1e-6);
	// a single circle (the can's lid alone) is no body
	WireFrameBuilder one("disc");
	one.circle({0, 0, 0}, 20);
	EXPECT_TRUE(revolutionBodiesOf(featuresOf(one.build())).empty());
}

// Property: for cylinders and cone frusta at random poses, every limb sample projects onto the
// outline of the projected surface (within 0.6 px, the outline being a polygon of the surface's
// sampled points), on both sides, and the sight ray grazes the surface there.
TEST(limbs, LimbsLieOnTheProjectedSilhouette)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> U(0, 1);
	int checked = 0;
	for (int trial = 0; trial < 40; ++trial)
	{
		const Frustum f{20 + 30 * U(rng), trial % 2 ? 20 + 30 * U(rng) : 0.0, 40 + 120 * U(rng)};
		const Frustum shape{f.r0, f.r1 > 0 ? f.r1 : f.r0, f.h};
		const Eigen::Isometry3d T = poseOf(2 * M_PI * U(rng), -M_PI / 2 - 0.9 * U(rng),
		                                   {-150 + 300 * U(rng), -100 + 200 * U(rng),
		                                    500 + 500 * U(rng)});
		const auto bodies = revolutionBodiesOf(featuresOf(shape.wireFrame()));
		ASSERT_EQ(bodies.size(), 1u);
		const Eigen::Vector3d c_O = T.inverse() * Eigen::Vector3d::Zero();  // left camera centre
		const auto samples = limbSamples(bodies[0], c_O, 3);
		ASSERT_GE(samples.size(), 4u) << "a camera off the axis sees two limbs";
		std::vector<cv::Point2f> hull;
		cv::convexHull(surfacePixels(shape, T, 0), hull);
		for (const auto& s : samples)
		{
			EXPECT_LT(distanceToOutline(hull, pixel(T * s.p_O, 0)), 0.6) << "trial " << trial;
			// on the surface, and the sight ray is perpendicular to the surface normal there
			const double k = (shape.r1 - shape.r0) / shape.h;
			const Eigen::Vector3d radial(s.p_O.x(), s.p_O.y(), 0);
			EXPECT_NEAR(radial.norm(), shape.r0 + k * s.p_O.z(), 1e-6);
			const Eigen::Vector3d n = radial.normalized() - k * Eigen::Vector3d::UnitZ();
			EXPECT_NEAR(n.normalized().dot((s.p_O - c_O).normalized()), 0, 1e-9);
			++checked;
		}
	}
	EXPECT_GT(checked, 40 * 20);
}

TEST(limbs, CameraOnTheAxisOfACylinderSeesNoLimb)
{
	const Frustum f{30, 30, 100};
	const auto bodies = revolutionBodiesOf(featuresOf(f.wireFrame()));
	ASSERT_EQ(bodies.size(), 1u);
	EXPECT_TRUE(limbSamples(bodies[0], {0, 0, 600}, 3).empty());
	EXPECT_FALSE(limbSamples(bodies[0], {0, 400, 600}, 3).empty());
}

namespace
{
/** Radius of @p b's profile at axial position z (−1 outside it). */
double profileRadius(const RevolutionBody& b, double z)
{
	for (const auto& s : b.profile)
		if (z >= s.z0_mm && z <= s.z1_mm)
			return s.r0_mm + (s.r1_mm - s.r0_mm) * (z - s.z0_mm) / (s.z1_mm - s.z0_mm);
	return -1;
}

/** Deepest inside the solid (mm) that the segment c→p gets, by fine steps. */
double deepestOnSegment(const RevolutionBody& b, const Eigen::Vector3d& c, const Eigen::Vector3d& p)
{
	double deepest = -1e9;
	for (int i = 0; i <= 20000; ++i)
	{
		const Eigen::Vector3d x = c + (p - c) * (i / 20000.0) - b.axis_point;
		const double z = x.dot(b.axis_dir), rho = (x - z * b.axis_dir).norm();
		const double r = profileRadius(b, z);
		if (r >= 0) deepest = std::max(deepest, r - rho);
	}
	return deepest;
}

mrolr::model::WireFrame bottle()
{
	WireFrameBuilder b("bottle");
	b.circle({0, 0, 0}, 35).circle({0, 0, 150}, 35).circle({0, 0, 190}, 14).circle({0, 0, 220}, 14);
	return b.build();
}
}  // namespace

// Property: the exact occlusion by the solid agrees with marching along the sight segment, for a
// body that is not convex (a bottle: body, shoulder cone, neck), random cameras and surface points.
TEST(limbs, SolidOcclusionAgreesWithMarchingAlongTheSightRay)
{
	const auto bodies = revolutionBodiesOf(featuresOf(bottle()));
	ASSERT_EQ(bodies.size(), 1u);
	const RevolutionBody& b = bodies[0];
	ASSERT_EQ(b.profile.size(), 3u);
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> U(0, 1);
	int hidden = 0, seen = 0;
	for (int trial = 0; trial < 400; ++trial)
	{
		const double az = 2 * M_PI * U(rng), el = -0.3 + 1.5 * U(rng), dist = 400 + 600 * U(rng);
		const Eigen::Vector3d c = b.axis_point + Eigen::Vector3d(dist * std::cos(el) * std::cos(az),
		                                                         dist * std::cos(el) * std::sin(az),
		                                                         dist * std::sin(el));
		const double z = b.profile.front().z0_mm +
		                 (b.profile.back().z1_mm - b.profile.front().z0_mm) * U(rng),
		             t = 2 * M_PI * U(rng);
		const Eigen::Vector3d p = b.axis_point + z * b.axis_dir +
		                          profileRadius(b, z) * Eigen::Vector3d(std::cos(t), std::sin(t), 0);
		EXPECT_TRUE(onSurface(b, p, 0.01));
		const double deepest = deepestOnSegment(b, c, p);
		const bool crosses = crossesSolid(b, c, p, 0.5);
		if (deepest > 1.0)
		{
			EXPECT_TRUE(crosses) << "trial " << trial << " depth " << deepest;
		}
		if (crosses)
		{
			EXPECT_GT(deepest, 0.4) << "trial " << trial;
		}
		(crosses ? hidden : seen)++;
	}
	EXPECT_GT(hidden, 50);
	EXPECT_GT(seen, 50);
}

// The ring where a bottle's neck meets its shoulder is seen from above in front; the convex polytope
// of the 3D verification hides it (it fills the neck), the exact solid does not. Behind the neck it
// is hidden either way.
TEST(limbs, NeckRingInFrontIsSeenWithTheExactSolid)
{
	const auto fs = featuresOf(bottle());
	const SelfOcclusion occ(fs);
	const Eigen::Vector3d camera(700, 0, 500), front(14, 0, 190), back(-14, 0, 190);
	EXPECT_TRUE(occ.hidden(camera, front)) << "the polytope fills the neck";
	EXPECT_FALSE(occ.hiddenOnBodies(camera, front));
	EXPECT_TRUE(occ.hiddenOnBodies(camera, back));
	// a point off every body (a line's sample above the bottle) is judged by the polytope
	EXPECT_EQ(occ.hiddenOnBodies(camera, {0, 0, 260}), occ.hidden(camera, {0, 0, 260}));
}

// A limb behind a handle is hidden by it (the polytope of the features off the body); one in the
// open is not, and a model that is all body never hides its limbs.
TEST(limbs, AHandleHidesTheLimbBehindIt)
{
	WireFrameBuilder b("mug");
	b.circle({0, 0, 0}, 50).circle({0, 0, 120}, 50);
	for (const double y : {-8.0, 8.0})  // the handle's two edges, as the built large cup has them
		b.arc({-50, y, 60}, Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX(), 30, -M_PI / 2,
		      M_PI / 2);
	const auto fs = featuresOf(b.build());
	const SelfOcclusion occ(fs);
	ASSERT_EQ(occ.revolutionBodies().size(), 1u);
	const Eigen::Vector3d camera(0, -700, 60);  // the handle points to -x, seen side-on
	int behind = 0, hidden_behind = 0;
	for (const auto& s : limbSamples(occ.revolutionBodies()[0], camera, 3))
	{
		if (s.p_O.x() > 0)
			EXPECT_FALSE(occ.hiddenLimb(camera, s.p_O)) << s.p_O.transpose();
		else if (s.p_O.z() > 45 && s.p_O.z() < 75)
			++behind, hidden_behind += occ.hiddenLimb(camera, s.p_O) ? 1 : 0;
	}
	ASSERT_GT(behind, 5);
	EXPECT_EQ(hidden_behind, behind);
	const SelfOcclusion can(featuresOf(makeCan()));
	for (const auto& s : limbSamples(can.revolutionBodies().at(0), camera, 3))
		EXPECT_FALSE(can.hiddenLimb(camera, s.p_O));
}

namespace
{
/** A can (cylinder r 33, h 115, about O's z) standing on a table, drawn by one camera: the table
 * in one grey, the side in another, the top (when it faces the camera) in a third; the outline is
 * the convex hull of the projected rims (exact for a convex solid). */
cv::Mat drawCan(const Eigen::Isometry3d& T_OinL, double cam_x_cv_mm)
{
	cv::Mat img(480, 640, CV_8U, cv::Scalar(90));
	const auto rim = [&](double z)
	{
		std::vector<cv::Point> px;
		for (int i = 0; i < 360; ++i)
		{
			const cv::Point2d q =
			    pixel(T_OinL * Eigen::Vector3d(33 * std::cos(i * M_PI / 180),
			                                   33 * std::sin(i * M_PI / 180), z),
			          cam_x_cv_mm) *
			    16.0;
			px.emplace_back(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
		}
		return px;
	};
	std::vector<cv::Point> both = rim(0), top = rim(115), hull;
	both.insert(both.end(), top.begin(), top.end());
	cv::convexHull(both, hull);
	cv::fillConvexPoly(img, hull, cv::Scalar(160), cv::LINE_AA, 4);
	const Eigen::Vector3d camera_L(cam_x_cv_mm, 0, 0);
	if ((T_OinL.linear() * Eigen::Vector3d::UnitZ()).dot(camera_L - T_OinL * Eigen::Vector3d(0, 0, 115)) > 0)
		cv::fillConvexPoly(img, top, cv::Scalar(220), cv::LINE_AA, 4);
	return img;
}

Eigen::Isometry3d canPose()
{
	// seen from above and in front, as on a table 700 mm away
	return poseOf(0.4, -M_PI / 2 - 0.6, {20, -40, 700});
}

struct CanPair
{
	mrolr::model::WireFrame wf = [] {
		WireFrameBuilder b("can");
		b.circle({0, 0, 0}, 33).circle({0, 0, 115}, 33);
		return b.build();
	}();
	std::vector<Feature> fs = featuresOf(wf);
	SelfOcclusion occ{fs};
	std::vector<EdgeSample> samples = edgeSamplesOf(wf, 3);
	ImageVerifier with{drawCan(canPose(), 0), drawCan(canPose(), -kBaseline_mm), calibration(),
	                   ImageVerificationOptions()};
	ImageVerifier without{drawCan(canPose(), 0), drawCan(canPose(), -kBaseline_mm), calibration(),
	                      [] {
		                      ImageVerificationOptions o;
		                      o.limbs = false;
		                      return o;
	                      }()};
};
}  // namespace

TEST(limbs, DrawnCanScoresHighAtItsPoseAndLower10MmAway)
{
	const CanPair p;
	const ImageScore at = p.with.score(p.samples, canPose(), &p.occ);
	const ImageScore rims_only = p.without.score(p.samples, canPose(), &p.occ);
	EXPECT_GE(at.score, 0.9);
	EXPECT_GT(at.considered, rims_only.considered) << "the limbs add samples";
	for (const Eigen::Vector3d& shift : {Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0)})
	{
		const Eigen::Isometry3d T = Eigen::Translation3d(shift) * canPose();
		EXPECT_LT(p.with.score(p.samples, T, &p.occ).score, at.score - 0.4) << shift.transpose();
	}
}

TEST(limbs, KeysAreOptionalCheckedAndRead)
{
	const std::string common = "[iv]\ncanny_low = 20\ncanny_high = 50\nedge_distance_px = 2\n"
	                           "min_score = 0.7\n";
	ImageVerificationOptions o;
	// a fresh file each time: CConfigFileMemory::setContent keeps the keys of earlier contents
	const auto load = [&o](const std::string& text)
	{
		mrpt::config::CConfigFileMemory cfg(text);
		o.loadFromConfigFile(cfg, "iv");
	};
	for (const std::string key : {"limbs", "revolution_visibility"})
	{
		// absent: the value stands (the struct's default, on, is the shipped one)
		ImageVerificationOptions off;
		(key == "limbs" ? off.limbs : off.revolution_visibility) = false;
		mrpt::config::CConfigFileMemory cfg(common);
		off.loadFromConfigFile(cfg, "iv");
		EXPECT_FALSE(key == "limbs" ? off.limbs : off.revolution_visibility) << key;
		EXPECT_TRUE(ImageVerificationOptions().limbs && ImageVerificationOptions().revolution_visibility);
		// given, it is checked
		try
		{
			load(common + key + " = maybe\n");
			FAIL() << key << " = maybe was accepted";
		}
		catch (const mrolr::util::ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
		}
	}
	load(common + "limbs = false\nrevolution_visibility = true\n");
	EXPECT_FALSE(o.limbs);
	EXPECT_TRUE(o.revolution_visibility);
	load(common + "limbs = true\nrevolution_visibility = false\n");
	EXPECT_TRUE(o.limbs);
	EXPECT_FALSE(o.revolution_visibility);
}
