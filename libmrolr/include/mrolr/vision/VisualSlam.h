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
#include <functional>
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
	bool jointly_rejected = false;            ///< matched, but not jointly compatible (stepJoint)
	std::optional<double> nis;                ///< its NIS (eq 5.36) when it was matched
	std::vector<std::string> added, deleted;  ///< map changes in this cycle
	/** The head turned to another feature than the last one measured (5.7). */
	bool saccade = false;
	/** Measurements that saccade costs (5.7 step 1, slam::measurementsLostBySaccade). Skipped for
	 * real with selection = saccade; only counted with largest_vs. */
	int measurements_lost = 0;
	bool waiting = false;  ///< no measurement: the head is still saccading (selection = saccade)
	CycleTimes times;
};

/** Runs the cycle on an ActiveSlamFilter with a StereoHeadDevice. Keeps one saved patch per mapped
 * feature, parallel to the filter's features. */
class VisualSlam
{
 public:
	/** @p model is the base model the saccade decision predicts with (5.7 step 3). */
	VisualSlam(slam::ActiveSlamFilter& filter, const geometry::BiSightHead& head,
	           const VisionOptions& options, const base::LabmateModel& model);

	/** A known feature (5.6.2) at @p p_FinW (W, metres) with its saved patch. */
	void addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
	                     const cv::Mat& patch);
	/** The same with the covariance @p P_FF (m²) of a saved map's feature, whose patch was saved
	 * with the head centre at @p p_viewinW (the viewpoint the 5.2.1 visibility rules refer to). */
	void addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
	                     const Eigen::Matrix3d& P_FF, const cv::Mat& patch,
	                     const std::optional<Eigen::Vector3d>& p_viewinW = std::nullopt);

	/** A feature named @p label acquired where the head is pointed, as an operator points it
	 * (5.6.2): the head fixates @p p_aim_inC0 (C0, m), the best Shi–Tomasi patch within
	 * [vision] known_search_box_px of the image centre is locked on (5.3) and initialised from
	 * its triangulation; the 5.7 deletion rule spares it. Returns its index, or nothing when it
	 * could not be locked on (@p why). */
	std::optional<size_t> acquireNamed(const std::string& label, const Eigen::Vector3d& p_aim_inC0,
	                                   StereoHeadDevice& device, std::string* why = nullptr);

	/** One cycle after the base moved by @p u (dt_s = 0: no motion, measure only). @p upcoming:
	 * the next planned controls, for the saccade decision (selection = saccade). */
	CycleRecord step(const base::WheelControl& u, StereoHeadDevice& device,
	                 const std::vector<base::WheelControl>& upcoming = {});

	/** One step's cycle with joint compatibility: predict with @p u, manage the map, then measure
	 * up to @p count visible features — the nearest known feature first (thesis 7.2(a)), then by
	 * largest Vs — without updating in between; the matches are accepted only as a jointly
	 * compatible set (slam::jointlyCompatible), then used to update. One record per feature
	 * measured (or one with measured = false). */
	std::vector<CycleRecord> stepJoint(const base::WheelControl& u, StereoHeadDevice& device,
	                                   int count);

	/** Before the base turns in place: the head turns the other way so that the feature it last
	 * measured stays in view at @p xv_after (the pose the turn should end at), and the first
	 * search after the turn is a short one; nothing when that feature would leave the head's
	 * reach. */
	void holdGaze(const Eigen::Vector3d& xv_after, StereoHeadDevice& device);

	/** After losing track (the caller has widened the vehicle's covariance): up to @p count known
	 * features within @p max_range_m and the head's reach, nearest first, sought in their (now
	 * wide) ellipses and accepted only as a jointly compatible set. One record per feature. */
	std::vector<CycleRecord> relocalise(StereoHeadDevice& device, int count, double max_range_m);

	/** Measures feature @p i now, without motion or selection (e.g. re-finding a known feature when
	 * the robot is back home, 5.6.2). Returns found = false if it is not visible. */
	CycleRecord measureFeature(size_t i, StereoHeadDevice& device);
	/** One frame of a recorded run (rawlog replay), where the head cannot be steered: predict with
	 * the odometry control @p u; then, if there is a pair (@p images may be null), acquire new
	 * features in it while fewer than min_visible_features are in view (boxes of acquire_box_px
	 * at the principal point and one box to its left and right, no fixation), and measure every
	 * mapped feature whose prediction falls inside both images, largest Vs (eq 5.147) first, each
	 * in its search ellipses (eqs 5.37–5.39) at the recorded angles. Returns one record per
	 * feature measured, or a single record with measured = false. */
	std::vector<CycleRecord> replayFrame(const base::WheelControl& u, const StereoImages* images);

	/** Indices of the visible features (5.2.1) whose predicted image positions lie inside both
	 * images of size @p size with the head at @p angles, patch included. */
	std::vector<size_t> featuresInView(const geometry::HeadAngles& angles, const cv::Size& size);

	/** Indices of the features the head could measure from the current estimate (5.2.1, 5.7). */
	std::vector<size_t> visibleFeatures();

	/** When set: true for a point (C0, m) the robot's own body hides or lies on (mission's
	 * SelfModel). Such a feature is not visible (not selected, not searched, no failure counted)
	 * and no feature is added there. */
	std::function<bool(const Eigen::Vector3d&)> self_occludes;

	const std::vector<cv::Mat>& patches() const { return patches_; }
	int featuresAdded() const { return added_; }
	int featuresDeleted() const { return deleted_; }

 private:
	void acquireFeatures(StereoHeadDevice& device, CycleRecord& r);
	void acquireInFrame(const StereoImages& images, CycleRecord& r);
	/** Adds the feature triangulated at @p p_GinC0 with @p patch unless a mapped one is there
	 * (label: "F<n>" when empty). */
	bool addFeature(const Eigen::Vector3d& p_GinC0, const cv::Mat& patch, CycleRecord& r,
	                const std::string& label = "");
	CycleRecord measureInFrame(size_t i, const StereoImages& images);
	void applyMeasurement(CycleRecord& r);
	bool isDuplicate(const Eigen::Vector3d& p_FinW);
	void selectFeature(CycleRecord& r);
	/** 5.7 steps 1–4; false when the head is (still) saccading and nothing is measured. */
	bool selectBySaccade(CycleRecord& r, const std::vector<base::WheelControl>& upcoming);
	void noteSaccade(CycleRecord& r);
	void measureSelected(StereoHeadDevice& device, CycleRecord& r);
	/** Saccade to the selected feature, search its ellipses and match it; no update. */
	void matchSelected(StereoHeadDevice& device, CycleRecord& r);
	void deleteFailed(CycleRecord& r);
	/** The features of one joint step: the nearest visible known one, then by largest Vs. */
	std::vector<size_t> chooseForStep(int count);
	/** The jointly compatible matches of @p records update the filter; every attempt recorded. */
	void applyJointly(std::vector<CycleRecord>& records);

	slam::ActiveSlamFilter& filter_;
	geometry::BiSightHead head_;
	VisionOptions options_;
	std::vector<cv::Mat> patches_;
	base::LabmateModel model_;
	int added_ = 0, deleted_ = 0, next_label_ = 1;
	std::vector<std::string> spared_;  ///< named features the 5.7 deletion rule keeps
	std::string tracked_;  ///< label of the feature the head fixates now
	Eigen::Vector3d head_h_ = Eigen::Vector3d::Zero();  ///< its ideal-head angles (eq 5.40), rad
	std::string pending_;  ///< selection = saccade: the feature the head is moving to
	int waiting_ = 0;      ///< cycles until the head arrives there
};

}  // namespace mrolr::vision
