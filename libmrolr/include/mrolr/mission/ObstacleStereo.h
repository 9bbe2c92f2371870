#pragma once
/** Dense stereo for obstacle mode (thesis 5.8.1.2): a stereo pair of the BiSight head is rectified
 * for its joint angles (stereo::calibrationFromHead, stereo::Rectifier), matched by OpenCV's
 * semi-global block matcher (cv::StereoSGBM) on images scaled by image_scale, and every matched
 * pixel becomes a 3D point in the base frame B: on the floor under the head centre C0, axes as C0
 * (x left, y up = height above the floor, z forward), metres. Only points whose height lies in
 * [min_height_m, max_height_m] are kept: the floor itself is no obstacle. */
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/mission/ObstacleOptions.h>
#include <mrolr/stereo/Rectifier.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <map>
#include <memory>
#include <tuple>
#include <vector>

namespace mrolr::mission
{
class ObstacleStereo
{
 public:
	ObstacleStereo(const geometry::BiSightHead& head, const ObstacleOptions& options);

	/** Points (B, m) above the floor seen in the pair @p left, @p right (8-bit grey or colour,
	 * the head's image size) taken at @p angles. Throws std::runtime_error for images of another
	 * size. */
	std::vector<Eigen::Vector3d> pointsAboveFloor(const cv::Mat& left, const cv::Mat& right,
	                                              const geometry::HeadAngles& angles);

	/** The disparity image (px at image_scale, CV_32F, negative where unmatched) of the last call.
	 */
	const cv::Mat& lastDisparity() const { return disparity_; }

 private:
	const stereo::Rectifier& rectifierFor(const geometry::HeadAngles& angles);
	cv::Mat disparityOf(const cv::Mat& left_rect, const cv::Mat& right_rect,
	                    const stereo::Rectifier& rect) const;

	geometry::BiSightHead head_;
	ObstacleOptions o_;
	/** One rectifier per joint setting (the looks repeat the same three settings). */
	std::map<std::tuple<double, double, double, double>, std::unique_ptr<stereo::Rectifier>> rect_;
	cv::Mat disparity_;
};

}  // namespace mrolr::mission
