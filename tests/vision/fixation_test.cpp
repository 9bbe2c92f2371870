// Fixation and lock-on (thesis 5.3): from a guess whose image is 10 px off the principal point the
// loop re-triangulates and locks on within 2 px in both images; it discards what it cannot fixate.
#include "TestScene.h"

#include <mrolr/vision/Fixation.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

using namespace mrolr;
using namespace mrolr::vision;

namespace
{
/** @p p turned about C0 so that fixating it leaves the true point about @p px pixels off centre. */
Eigen::Vector3d guessOffBy(const Eigen::Vector3d& p, double px, const Eigen::Vector3d& axis)
{
	return Eigen::AngleAxisd(std::atan(px / 807.0), axis.normalized()) * p;
}
}  // namespace

class FixationTest : public ::testing::Test
{
 protected:
	geometry::BiSightHead head = test::configuredHead();
	VisionOptions options = test::configuredVision();
	SyntheticStereoHead device{head, 2.0, 21};
	Eigen::Vector3d p_true{0.3, 0.25, 2.2};

	void SetUp() override
	{
		device.setPoints(test::texturedPoints({p_true, {-0.5, 0.1, 3.0}, {0.6, -0.2, 1.5}}));
		device.moveTo(head.fixate(p_true));
	}
};

TEST_F(FixationTest, ConvergesFromATenPixelOffset)
{
	const cv::Mat patch = extractPatch(device.grab().left, {320, 240}, options.patch_size_px);
	for (const Eigen::Vector3d& axis :
	     {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0)})
	{
		const Eigen::Vector3d guess = guessOffBy(p_true, 10, axis);
		// the guess really is about 10 px off in the left image
		const auto off = head.project(p_true, head.fixate(guess));
		EXPECT_GT(std::hypot(off.uL - 320, off.vL - 240), 7.0);
		const FixationResult r = fixateOnPatch(device, head, patch, guess, options);
		ASSERT_TRUE(r.locked) << r.failure;
		EXPECT_GE(r.attempts, 2);
		EXPECT_TRUE(isLockedOn(r.pixels, head.camera(), options.lockon_radius_px));
		const auto truth = head.project(p_true, r.angles);
		EXPECT_TRUE(isLockedOn(truth, head.camera(), options.lockon_radius_px + 0.5));
		EXPECT_LT((r.p_GinC0 - p_true).norm(), 0.03);
	}
}

TEST_F(FixationTest, DiscardsAfterTheConfiguredAttempts)
{
	const cv::Mat patch = extractPatch(device.grab().left, {320, 240}, options.patch_size_px);
	options.lockon_radius_px = 0;  // unattainable: sub-pixel matches are never exact
	options.fixation_max_attempts = 3;
	const FixationResult r = fixateOnPatch(
	    device, head, patch, guessOffBy(p_true, 10, Eigen::Vector3d::UnitY()), options);
	EXPECT_FALSE(r.locked);
	EXPECT_EQ(r.attempts, 3);
	EXPECT_NE(r.failure.find("no lock-on after 3 attempts"), std::string::npos) << r.failure;
}

TEST_F(FixationTest, LostPatchAndJointLimitsAreReported)
{
	const cv::Mat other = makeTexture(31, 999)(cv::Rect(9, 9, 13, 13)).clone();
	FixationResult r = fixateOnPatch(device, head, other, p_true, options);
	EXPECT_FALSE(r.locked);
	EXPECT_NE(r.failure.find("patch not found"), std::string::npos) << r.failure;
	const cv::Mat patch = extractPatch(device.grab().left, {320, 240}, options.patch_size_px);
	r = fixateOnPatch(device, head, patch, {0, 5, 0.5}, options);  // straight up: tilt limit
	EXPECT_FALSE(r.locked);
	EXPECT_NE(r.failure.find("cannot fixate"), std::string::npos) << r.failure;
}

TEST_F(FixationTest, AcquiresTheFeatureInTheSearchBoxAndLocksOn)
{
	device.moveTo(geometry::HeadAngles{});  // looking straight ahead, no vergence
	const auto px = head.project(p_true, device.angles());
	const cv::Rect box(int(px.uL) - 40, int(px.vL) - 40, 80, 80);
	const Acquisition a = acquireFeature(device, head, box, options);
	ASSERT_TRUE(a.ok) << a.failure;
	EXPECT_EQ(a.patch.size(), cv::Size(13, 13));
	EXPECT_TRUE(box.contains(cv::Point(int(a.corner.uv.x()), int(a.corner.uv.y()))));
	// the locked point is the textured point (its 31 px texture spans about 3 cm at 2.2 m)
	EXPECT_LT((a.fixation.p_GinC0 - p_true).norm(), 0.1);
	EXPECT_TRUE(isLockedOn(a.fixation.pixels, head.camera(), options.lockon_radius_px));
}

TEST_F(FixationTest, AcquisitionInAnEmptyBoxReportsWhy)
{
	device.moveTo(geometry::HeadAngles{});
	const Acquisition a = acquireFeature(device, head, cv::Rect(560, 10, 60, 60), options);
	EXPECT_FALSE(a.ok);
	EXPECT_NE(a.failure.find("no Shi-Tomasi feature"), std::string::npos)
	    << a.failure << " lambda " << a.corner.min_eigenvalue;
}
