#pragma once
/** The measurement cycle of vision-driven EKF-SLAM (thesis 5.5–5.7, 7.2(a)–(c)):
 *   predict (Labmate model) → manage the map (acquire new features while fewer than
 *   min_visible_features are visible, 5.7) → select the visible feature with the largest
 *   innovation volume Vs (eq 5.147) → search: saccade to it and project the ellipses of its
 *   innovation covariance into both images (eqs 5.37–5.39) → grab → match the saved patch by NSSD
 *   (eq 5.21) and triangulate → update the filter with the measured ideal-head angles (eq 5.40)
 *   through its χ² gate → delete features that failed more than half of their last attempts.
 * Each stage is timed so that the robot's processing can be reported apart from image capture. */

#include <mrolr/slam/ActiveSlamFilter.h>
#include <mrolr/vision/FeatureMeasurement.h>
#include <mrolr/vision/StereoHeadDevice.h>
#include <mrolr/vision/VisionOptions.h>

#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace mrolr::vision
{
/** Wall-clock time of each stage of one cycle, milliseconds. grab_ms is image capture (rendering in
 * simulation) and is not robot processing. */
struct CycleTimes
{
	double predict_ms = 0, manage_ms = 0, select_ms = 0, search_ms = 0, grab_ms = 0, match_ms = 0,
	       update_ms = 0;
	/** Everything but image capture and map management (acquisition saccades). */
	double processingMs() const
	{
		return predict_ms + select_ms + search_ms + match_ms + update_ms;
	}
	CycleTimes& operator+=(const CycleTimes& o);
};

/** What one cycle decided; written to the decisions log. */
struct CycleRecord
{
	bool measured = false;  ///< a feature was selected and searched for
	size_t feature = 0;     ///< its index in the map at selection time
	std::string label;
	double vs = 0;                            ///< its innovation volume Vs (eq 5.147), rad³
	FeatureMeasurement measurement;           ///< ellipses, matches, scores, measured h
	bool accepted = false;                    ///< matched and passed the χ² gate
	std::vector<std::string> added, deleted;  ///< map changes in this cycle
	CycleTimes times;
};

/** Runs the cycle on an ActiveSlamFilter with a StereoHeadDevice. Keeps one saved patch per mapped
 * feature, parallel to the filter's features. */
class VisualSlam
{
 public:
	VisualSlam(slam::ActiveSlamFilter& filter, const geometry::BiSightHead& head,
	           const VisionOptions& options);

	/** A known feature (5.6.2) at @p p_FinW (W, metres) with its saved patch. */
	void addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
	                     const cv::Mat& patch);

	/** One cycle after the base moved by @p u (dt_s = 0: no motion, measure only). */
	CycleRecord step(const base::WheelControl& u, StereoHeadDevice& device);

	/** Measures feature @p i now, without motion or selection (e.g. re-finding a known feature when
	 * the robot is back home, 5.6.2). Returns found = false if it is not visible. */
	CycleRecord measureFeature(size_t i, StereoHeadDevice& device);
	/** Indices of the features the head could measure from the current estimate (5.2.1, 5.7). */
	std::vector<size_t> visibleFeatures();

	const std::vector<cv::Mat>& patches() const { return patches_; }
	int featuresAdded() const { return added_; }
	int featuresDeleted() const { return deleted_; }

 private:
	void acquireFeatures(StereoHeadDevice& device, CycleRecord& r);
	bool isDuplicate(const Eigen::Vector3d& p_FinW);
	void selectFeature(CycleRecord& r);
	void measureSelected(StereoHeadDevice& device, CycleRecord& r);
	void deleteFailed(CycleRecord& r);

	slam::ActiveSlamFilter& filter_;
	geometry::BiSightHead head_;
	VisionOptions options_;
	std::vector<cv::Mat> patches_;
	int added_ = 0, deleted_ = 0, next_label_ = 1;
};

}  // namespace mrolr::vision
