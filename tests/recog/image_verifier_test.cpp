// Verification in the stereo images (ImageVerifier.h): a model drawn into a synthetic stereo pair
// scores high at its pose and low when shifted, turned or replaced by another object; the
// refinement moves a perturbed pose towards the drawn one; bad input is reported.
#include "drawn_box_pair.h"
#include "recog_test_util.h"
#include "synthetic_rig.h"

#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/imgproc.hpp>

#include <sstream>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
using test::boxPose;
using test::calibration;
using test::draw;
using test::fillPolygon;
using test::kBaseline_mm;
using test::Pair;
}  // namespace

TEST(ImageVerifier, TruePoseScoresHighInBothImages)
{
	const Pair p;
	const ImageScore s = p.images.score(p.box, boxPose(), &p.occ);
	EXPECT_GE(s.score, 0.9);
	EXPECT_GE(s.per_image[0], 0.9);
	EXPECT_GE(s.per_image[1], 0.9);
	EXPECT_GE(s.considered, ImageVerificationOptions().min_samples);
}

TEST(ImageVerifier, ShiftedOrTurnedPoseScoresLow)
{
	const Pair p;
	const Eigen::Isometry3d shifted = Eigen::Translation3d(15, 0, 0) * boxPose();
	const Eigen::Isometry3d turned =
	    boxPose() * Eigen::AngleAxisd(25 * M_PI / 180, Eigen::Vector3d::UnitZ());
	EXPECT_LT(p.images.score(p.box, shifted, &p.occ).score, 0.3);
	EXPECT_LT(p.images.score(p.box, turned, &p.occ).score, 0.4);
}

TEST(ImageVerifier, AbsentObjectScoresLow)
{
	const Pair p;
	for (const auto& other : {makeCup(), makeCan(), makeTapeRoll()})
	{
		const auto fs = featuresOf(other);
		const SelfOcclusion occ(fs);
		EXPECT_LT(p.images.score(fs, boxPose(), &occ).score, 0.35) << other.name;
	}
}

TEST(ImageVerifier, RefinementBringsAPerturbedPoseBackOntoTheEdges)
{
	const Pair p;
	const Eigen::Isometry3d start = Eigen::Translation3d(2.5, -2, 1.5) * boxPose() *
	                                Eigen::AngleAxisd(2 * M_PI / 180, Eigen::Vector3d::UnitX());
	const auto samples = edgeSamplesOf(p.box, 3);
	const Eigen::Isometry3d T = p.images.refine(samples, start, &p.occ, upAxisPoints(p.box));
	const auto across = [](const Eigen::Isometry3d& A)
	{ return (A.translation() - boxPose().translation()).head<2>().norm(); };
	// the images fix the pose across the view well and along it weakly (at 650 mm a millimetre of
	// depth is 0.2 px of disparity): the refined pose fits the images as well as the drawn one
	// (score within 0.02) and is nearer to it across the view, not necessarily on it
	EXPECT_LT(across(T), 0.75 * across(start));
	EXPECT_LT(test::rotationErrorDeg(T, boxPose()), 3.0);
	EXPECT_GE(p.images.score(samples, T, &p.occ).score,
	          p.images.score(samples, boxPose(), &p.occ).score - 0.02);
	EXPECT_LT(p.images.score(samples, start, &p.occ).score, 0.5);
}

// The recogniser with images: the exact scene of the box is recognised and judged in the images;
// the cup, absent, is not found.
TEST(ImageVerifier, RecognizerAcceptsByImageScore)
{
	const Pair p;
	const auto opts = RecognitionOptions::defaults();
	const Recognizer rec(makeStaplerBox(), opts);
	std::vector<Feature> scene;
	for (const auto& f : p.box) scene.push_back(f.transformed(boxPose()));
	const auto r = rec.recognize(scene, {std::nullopt, std::cref(p.images), std::nullopt});
	ASSERT_TRUE(r.found);
	EXPECT_GE(r.image_score.value_or(0), 0.9);
	// across the view within a pixel (650 mm / 700 px); in depth within 5 mm (a pixel of
	// disparity is 5 mm at 650 mm with the 120 mm baseline)
	const Eigen::Vector3d error = r.T_OinS.translation() - boxPose().translation();
	EXPECT_LT(error.head<2>().norm(), 650 / test::kFocal_px) << error.transpose();
	EXPECT_LT(std::abs(error.z()), 5.0);
	// found at the first level, confirmed at the second from the same pose: refined once
	EXPECT_GE(r.image_refinements, 1);
	EXPECT_GE(r.image_refinements_reused, 1);
	EXPECT_FALSE(Recognizer(makeCup(), opts)
	                 .recognize(scene, {std::nullopt, std::cref(p.images), std::nullopt})
	                 .found);
	EXPECT_FALSE(rec.recognize(scene).image_score);  // without images: no image score
}

TEST(ImageVerifier, BadInputIsReported)
{
	const auto c = calibration();
	const cv::Mat ok(480, 640, CV_8U, cv::Scalar(0)), small(240, 320, CV_8U, cv::Scalar(0));
	const ImageVerificationOptions o;
	EXPECT_THROW(ImageVerifier(cv::Mat(), ok, c, o), std::invalid_argument);
	try
	{
		ImageVerifier(ok, small, c, o);
		FAIL() << "a right image of another size was accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("calibration"), std::string::npos) << e.what();
	}
	EXPECT_THROW(ImageVerifier(cv::Mat(480, 640, CV_32F), ok, c, o), std::invalid_argument);
	// an image without edges supports nothing and does not fail
	const ImageVerifier blank(ok, ok, c, o);
	const auto box = featuresOf(makeStaplerBox());
	EXPECT_EQ(blank.score(box, boxPose(), nullptr).score, 0.0);
}

TEST(ImageVerifier, OptionsNameTheBadKey)
{
	mrpt::config::CConfigFileMemory cfg;
	std::ostringstream defaults;
	ImageVerificationOptions().dump(defaults);
	std::string bad_canny = "[iv]\n" + defaults.str();  // every key; canny_high below canny_low
	for (const auto& [key, value] : {std::pair{"canny_low = ", "50"}, {"canny_high = ", "20"}})
	{
		const size_t at = bad_canny.find(key) + std::string(key).size();
		bad_canny.replace(at, bad_canny.find('\n', at) - at, value);
	}
	cfg.setContent(bad_canny);
	ImageVerificationOptions o;
	try
	{
		o.loadFromConfigFile(cfg, "iv");
		FAIL() << "canny_high below canny_low was accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("canny_high"), std::string::npos) << e.what();
	}
	// a fresh file: CConfigFileMemory::setContent keeps the keys of earlier contents
	const mrpt::config::CConfigFileMemory partial(
	    std::string("[iv]\nblur_sigma_px = 1\ncanny_low = 20\n"));
	EXPECT_THROW(o.loadFromConfigFile(partial, "iv"), mrolr::util::ConfigError);
	// every key as dumped, one key out of range
	std::ostringstream all;
	ImageVerificationOptions().dump(all);
	std::string text = "[iv]\n" + all.str();
	const std::string key = "min_in_image_fraction = ";
	text.replace(text.find(key), text.find('\n', text.find(key)) - text.find(key), key + "1.5");
	const mrpt::config::CConfigFileMemory bad(text);
	try
	{
		o.loadFromConfigFile(bad, "iv");
		FAIL() << "min_in_image_fraction 1.5 was accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("min_in_image_fraction"), std::string::npos)
		    << e.what();
	}
}

// The shipped [image_verification] equals the defaults (tests and the mission use the defaults).
TEST(ImageVerifier, ShippedOptionsAreTheDefaults)
{
	const mrpt::config::CConfigFile cfg(mrolr::util::requireProjectFile("config/recognition.ini"));
	ImageVerificationOptions shipped;
	shipped.loadFromConfigFile(cfg, "image_verification");
	std::ostringstream a, b;
	shipped.dump(a);
	ImageVerificationOptions().dump(b);
	EXPECT_EQ(a.str(), b.str());
}

namespace
{
/** A flat square occluder in L at depth @p z_mm covering x_L in [x0, x1], y_L in [-200, 200]:
 * its corners (for drawing) and its outline sampled every 5 mm as an Occluder (identity pose). */
std::vector<Eigen::Vector3d> squareCorners(double x0, double x1, double z_mm)
{
	return {{x0, -200, z_mm}, {x1, -200, z_mm}, {x1, 200, z_mm}, {x0, 200, z_mm}};
}

Occluder squareOccluder(const std::vector<Eigen::Vector3d>& corners)
{
	Occluder o;
	for (size_t i = 0; i < corners.size(); ++i)
	{
		const Eigen::Vector3d a = corners[i], b = corners[(i + 1) % corners.size()];
		const int n = static_cast<int>((b - a).norm() / 5);
		for (int k = 0; k < n; ++k)
			o.samples_O.push_back({a + (b - a) * k / n, (b - a).normalized(), 0});
	}
	return o;
}

/** The box of Pair with @p corners painted over it in the background grey (an object in front). */
ImageVerifier occludedPair(const std::vector<Eigen::Vector3d>& corners)
{
	cv::Mat l = draw(boxPose(), 0), r = draw(boxPose(), -kBaseline_mm);
	fillPolygon(l, corners, 0, 20);
	fillPolygon(r, corners, -kBaseline_mm, 20);
	return ImageVerifier(l, r, calibration(), ImageVerificationOptions());
}
}  // namespace

// Mutual occlusion (MutualOcclusion.h): the samples behind a recognised object in front are left
// out, so the part of the box that is still visible scores as it would unoccluded.
TEST(ImageVerifier, SamplesBehindAnOccluderAreLeftOut)
{
	const Pair p;
	const auto corners = squareCorners(10, 400, 450);
	const ImageVerifier hidden = occludedPair(corners);
	const ImageScore before = hidden.score(p.box, boxPose(), &p.occ);
	EXPECT_LT(before.score, 0.7) << "the painted square hides too little of the box";
	EXPECT_EQ(before.occluded, 0);
	const ImageScore after =
	    hidden.withOccluders({squareOccluder(corners)}).score(p.box, boxPose(), &p.occ);
	EXPECT_GT(after.occluded, 0);
	EXPECT_GE(after.score, 0.85);
	EXPECT_LT(after.considered, before.considered);
	EXPECT_EQ(after.considered + after.occluded, before.considered);
}

TEST(ImageVerifier, AnOccluderBehindTheObjectHidesNothing)
{
	const Pair p;
	const auto corners = squareCorners(10, 400, 900);  // behind the box (at 650 mm)
	const ImageScore s =
	    p.images.withOccluders({squareOccluder(corners)}).score(p.box, boxPose(), &p.occ);
	EXPECT_EQ(s.occluded, 0);
	EXPECT_NEAR(s.score, p.images.score(p.box, boxPose(), &p.occ).score, 1e-12);
}

TEST(ImageVerifier, AMostlyOccludedPoseScoresZero)
{
	const Pair p;
	const auto corners = squareCorners(-400, 400, 450);  // covers the whole box
	const ImageScore s = occludedPair(corners)
	                         .withOccluders({squareOccluder(corners)})
	                         .score(p.box, boxPose(), &p.occ);
	EXPECT_GT(s.occluded, 0);
	EXPECT_LT(s.considered,
	          ImageVerificationOptions().min_unoccluded_fraction * (s.considered + s.occluded));
	EXPECT_EQ(s.score, 0);
}

// An object standing mostly outside the view: its few edges inside fit the images exactly (drawn
// there), yet the pose scores 0 unless min_in_image_fraction is lowered — a few edges at the
// image border are what clutter fits by chance.
TEST(ImageVerifier, APoseMostlyOutsideTheImagesScoresZero)
{
	const Pair p;
	const Eigen::Isometry3d aside = Eigen::Translation3d(-400, 0, 0) * boxPose();  // to the right
	const cv::Mat l = draw(aside, 0), r = draw(aside, -kBaseline_mm);
	const ImageVerifier images(l, r, calibration(), ImageVerificationOptions());
	const ImageScore s = images.score(p.box, aside, &p.occ);
	ASSERT_GE(s.considered, ImageVerificationOptions().min_samples);  // enough to judge
	EXPECT_GT(s.outside, s.considered);
	EXPECT_EQ(s.score, 0);
	ImageVerificationOptions lenient;
	lenient.min_in_image_fraction = 0;
	EXPECT_GT(ImageVerifier(l, r, calibration(), lenient).score(p.box, aside, &p.occ).score, 0.8);
	// at the drawn pose in view nothing is outside
	EXPECT_EQ(p.images.score(p.box, boxPose(), &p.occ).outside, 0);
}

// count() leaves out the direction of the nearest edge from 2 px past the cost's cap on
// (EdgeImageVisit.h's kFar_px): that holds because the distance to the edges changes by at most
// √2 px from a pixel to any of its eight neighbours. Checked on the drawn pair and on noise,
// whose edges are everywhere.
TEST(ImageVerifier, DistanceChangesByAtMostRootTwoToANeighbour)
{
	cv::Mat noise(480, 640, CV_8U);
	cv::randu(noise, 0, 256);
	cv::Mat sparse = cv::Mat::zeros(480, 640, CV_8U);  // a few edges far apart
	cv::circle(sparse, {100, 100}, 30, cv::Scalar(255), 3);
	cv::line(sparse, {400, 50}, {600, 430}, cv::Scalar(200), 2);
	const Pair p;
	const ImageVerifier others(noise, sparse, calibration(), ImageVerificationOptions());
	double worst = 0;
	for (const ImageVerifier* v : {&p.images, &others})
		for (int i = 0; i < 2; ++i)
		{
			const cv::Mat& d = v->image(i).distance();
			for (int y = 0; y + 1 < d.rows; ++y)
				for (int x = 0; x + 1 < d.cols; ++x)
					for (const auto& [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}})
					{
						if (y + dy < 0) continue;
						worst = std::max(worst, std::abs(static_cast<double>(d.at<float>(y, x)) -
						                                 d.at<float>(y + dy, x + dx)));
					}
		}
	EXPECT_LE(worst, std::sqrt(2.0) + 1e-6);
	EXPECT_GT(worst, 0.9) << "the images have edges and distances";
}

// count() reads the class of a sample's distance (supported, under the cost's cap, beyond it)
// from a byte map drawn for the options' cap, and computes it from the distance for any other
// cap: with the options' cap and with the next larger number the counts are the same and the
// costs differ by no more than the caps, at poses on and off the drawn box. Without a cap (0,
// what a score without its cost asks) the counts are the same too.
TEST(ImageVerifier, CountsWithTheOptionsCapAsWithAnyOther)
{
	const Pair p;
	const double cap_px = ImageVerificationOptions().truncate_px;
	const double other_px = std::nextafter(cap_px, 1e9);
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	int supported = 0, below_cap = 0;
	for (int k = 0; k < 40; ++k)
	{
		const Eigen::Isometry3d T = Eigen::Translation3d(0.3 * k - 6, 0.1 * k, 0) * boxPose() *
		                            Eigen::AngleAxisd(0.02 * k, Eigen::Vector3d::UnitZ());
		for (int i = 0; i < 2; ++i)
		{
			const ImageCount a = p.images.image(i).count(samples, T, cap_px);
			const ImageCount b = p.images.image(i).count(samples, T, other_px);
			EXPECT_EQ(a.considered, b.considered);
			EXPECT_EQ(a.supported, b.supported);
			EXPECT_EQ(a.occluded, b.occluded);
			EXPECT_EQ(a.outside, b.outside);
			EXPECT_NEAR(a.cost_px2, b.cost_px2, 1e-9 * (1 + b.cost_px2)) << k << " " << i;
			const ImageCount c = p.images.image(i).count(samples, T, 0);
			EXPECT_EQ(c.considered, a.considered);
			EXPECT_EQ(c.supported, a.supported);
			EXPECT_EQ(c.occluded, a.occluded);
			EXPECT_EQ(c.outside, a.outside);
			EXPECT_EQ(c.cost_px2, 0);
			supported += a.supported;
			below_cap += a.cost_px2 < a.considered * cap_px * cap_px ? 1 : 0;
		}
	}
	EXPECT_GT(supported, 1000);
	EXPECT_GT(below_cap, 40);
}
