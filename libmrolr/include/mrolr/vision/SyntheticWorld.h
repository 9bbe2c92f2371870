#pragma once
/** A moving robot's stereo head in a world of textured point landmarks (W, metres): the landmarks
 * are re-expressed in C0 for the true vehicle pose (eq 5.35) and rendered by SyntheticStereoHead.
 * Used by the vision tests and bench/vision; the full lab renderer lives in the sim area. */

#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/vision/SyntheticStereoHead.h>

#include <string>
#include <vector>

namespace mrolr::vision
{
/** A named landmark in W with its texture. */
struct TexturedLandmark
{
	std::string name;
	Eigen::Vector3d p_inW = Eigen::Vector3d::Zero();  ///< metres, W (x left, y up, z forward)
	cv::Mat texture;                                  ///< CV_8UC1, odd sides
};

/** StereoHeadDevice on a vehicle whose true pose is set by the caller. */
class SyntheticWorld : public StereoHeadDevice
{
 public:
	SyntheticWorld(const geometry::BiSightHead& head, std::vector<TexturedLandmark> landmarks,
	               double noise_sigma = 2.0, std::uint64_t seed = 1);

	/** The true vehicle pose x_v = (z, x, φ) in W; the landmarks move in C0 accordingly. */
	void setVehicle(const Eigen::Vector3d& x_true);
	const Eigen::Vector3d& vehicle() const { return x_true_; }
	const std::vector<TexturedLandmark>& landmarks() const { return landmarks_; }

	void moveTo(const geometry::HeadAngles& angles) override { head_device_.moveTo(angles); }
	geometry::HeadAngles angles() const override { return head_device_.angles(); }
	StereoImages grab() override { return head_device_.grab(); }

 private:
	slam::HeadConstants constants_;
	std::vector<TexturedLandmark> landmarks_;
	SyntheticStereoHead head_device_;
	Eigen::Vector3d x_true_ = Eigen::Vector3d::Zero();
};

}  // namespace mrolr::vision
