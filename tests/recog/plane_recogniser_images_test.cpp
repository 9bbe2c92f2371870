// The recogniser with the support plane and a stereo pair (PlaneHypotheses.h, ImageVerifier.h): a
// box drawn into a synthetic pair is found from one horizontal line, or from two vertical edges,
// when the plane is given; not without it, not with the hypotheses turned off.
#include "plane_test_util.h"
#include "recog_test_util.h"

#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/plane/PlaneHypotheses.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/SyntheticObjects.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

using namespace mrolr::recog;
using namespace mrolr::sim;
using namespace mrolr::recog::plane_test;

namespace
{
constexpr double kFocal_px = 700, kBaseline_mm = 120;

mrolr::stereo::StereoCalibration calibration()
{
	mrolr::stereo::StereoCalibration c;
	c.image_size = cv::Size(640, 480);
	c.K_left = c.K_right = cv::Matx33d(kFocal_px, 0, 320, 0, kFocal_px, 240, 0, 0, 1);
	c.t_LinR_mm = cv::Vec3d(-kBaseline_mm, 0, 0);
	return c;
}

cv::Point pixel16(const Eigen::Vector3d& p_L, double cam_x_cv_mm)
{
	const Eigen::Vector3d c(-p_L.x() + cam_x_cv_mm, -p_L.y(), p_L.z());
	return {static_cast<int>(std::lround(16 * (kFocal_px * c.x() / c.z() + 320))),
	        static_cast<int>(std::lround(16 * (kFocal_px * c.y() / c.z() + 240)))};
}

/** The model's edges not hidden by itself, drawn 2 px wide by one camera of the pair. */
cv::Mat drawEdges(const mrolr::model::WireFrame& m, const Eigen::Isometry3d& T_OinL,
                  double cam_x_cv_mm)
{
	cv::Mat img(480, 640, CV_8U, cv::Scalar(20));
	const auto fs = featuresOf(m);
	const SelfOcclusion occ(fs);
	const Eigen::Vector3d cam_O = T_OinL.inverse() * Eigen::Vector3d(cam_x_cv_mm, 0, 0);
	const auto samples = edgeSamplesOf(m, 1.0);
	for (size_t k = 1; k < samples.size(); ++k)
	{
		const auto &a = samples[k - 1], &b = samples[k];
		if (a.feature != b.feature || (a.p_O - b.p_O).norm() > 3) continue;
		if (occ.hidden(cam_O, a.p_O) || occ.hidden(cam_O, b.p_O)) continue;
		cv::line(img, pixel16(T_OinL * a.p_O, cam_x_cv_mm), pixel16(T_OinL * b.p_O, cam_x_cv_mm),
		         cv::Scalar(200), 2, cv::LINE_AA, 4);
	}
	return img;
}

/** Rotation error (deg) of the stapler box's pose @p T against @p truth, modulo the box's half
 * turn about its axis, and the distance (mm) between their box centres (27 mm up). */
std::pair<double, double> boxPoseError(const Eigen::Isometry3d& T, const Eigen::Isometry3d& truth)
{
	const Eigen::Isometry3d turned = T * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ());
	const double rot =
	    std::min(test::rotationErrorDeg(T, truth), test::rotationErrorDeg(turned, truth));
	const Eigen::Vector3d c(0, 0, 27);
	return {rot, (T * c - truth * c).norm()};
}
}  // namespace

// With the stereo pair, the recogniser finds the stapler box from one of its horizontal lines (a
// fragment): the cliques have nothing to match, the plane hypotheses do; without the plane it is
// not found; the cup is not found from the same line.
TEST(PlaneHypotheses, RecogniserFindsABoxFromOneLineInTheImages)
{
	const auto box = makeStaplerBox();
	const auto fs = featuresOf(box);
	const auto T = upright(table(), {30, -190, 640}, 0.5);
	const ImageVerifier images(drawEdges(box, T, 0), drawEdges(box, T, -kBaseline_mm),
	                           calibration(), ImageVerificationOptions());
	const std::vector<Feature> scene = {fragment(fs[longestLineAt(fs, 0)], 0.7).transformed(T)};
	const SupportPlane plane = table();
	const auto opts = RecognitionOptions::defaults();
	const Recognizer rec(box, opts);
	EXPECT_FALSE(rec.recognize(scene, {plane.n_S, std::cref(images), std::nullopt}).found);
	const auto r = rec.recognize(scene, {plane.n_S, std::cref(images), plane});
	ASSERT_TRUE(r.found);
	EXPECT_EQ(r.origin, Origin::SupportPlane);
	EXPECT_GE(r.image_score.value_or(0), 0.7);
	const auto [rot, centre] = boxPoseError(r.T_OinS, T);
	EXPECT_LT(rot, 3.0);
	EXPECT_LT(centre, 5.0);
	EXPECT_FALSE(Recognizer(makeCup(), opts).recognize(scene, {plane.n_S, std::cref(images), plane}).found);
	auto off = opts;
	off.plane.enable = false;
	EXPECT_FALSE(Recognizer(box, off).recognize(scene, {plane.n_S, std::cref(images), plane}).found);
}

// The same box seen by two of its vertical edges only (fragments, as stereo gives them against a
// wall) is found from the edge pair; not when an edge-pair answer needs an image score no pose
// reaches, nor with edge pairs off.
TEST(PlaneHypotheses, RecogniserFindsABoxFromTwoVerticalEdgesInTheImages)
{
	const auto box = makeStaplerBox();
	const auto T = upright(table(), {30, -190, 640}, 2.0);
	const ImageVerifier images(drawEdges(box, T, 0), drawEdges(box, T, -kBaseline_mm),
	                           calibration(), ImageVerificationOptions());
	const Eigen::Vector3d a(80, -22.5, 0), b(80, 22.5, 0), lo(0, 0, 10), hi(0, 0, 45);
	const std::vector<Feature> scene = {lineFeature(T * (a + lo), T * (a + hi)),
	                                    lineFeature(T * (b + hi), T * (b + lo))};
	const SupportPlane plane = table();
	const auto opts = RecognitionOptions::defaults();
	const auto r = Recognizer(box, opts).recognize(scene, {plane.n_S, std::cref(images), plane});
	ASSERT_TRUE(r.found);
	EXPECT_EQ(r.origin, Origin::SupportPlane);
	EXPECT_GE(r.image_score, opts.plane.edge_pair_min_image_score);
	const auto [rot, centre] = boxPoseError(r.T_OinS, T);
	EXPECT_LT(rot, 3.0);
	EXPECT_LT(centre, 5.0);
	auto strict = opts;
	strict.plane.edge_pair_min_image_score = 1.0;
	EXPECT_FALSE(Recognizer(box, strict).recognize(scene, {plane.n_S, std::cref(images), plane}).found);
	auto off = opts;
	off.plane.edge_pair_hypotheses = false;
	EXPECT_FALSE(Recognizer(box, off).recognize(scene, {plane.n_S, std::cref(images), plane}).found);
}

