#pragma once
/** Calibrating T_C0inA where the robot stands, before it grasps (thesis 6.7, eq 6.7.2; the thesis
 * measured it once by hand). The arm presents its hand's ArUco marker ([arm_marker],
 * arm/MountCalibration.h) at `poses` known arm poses around the object, above the table top; at
 * each the head fixates where the nominal T_C0inA predicts the marker, grabs a stereo pair, finds
 * the marker in both images (stereo/ArucoMarker.h) and triangulates its centre (eqs 4.34–4.50).
 * T_C0inA is the least-squares rigid fit of the marker's positions in C0 to those of the forward
 * kinematics in A (Umeyama). A pose the arm cannot reach, or whose marker is not seen in both
 * images (the arm hides it, it is out of view), is skipped; with fewer than `min_poses` sightings,
 * a residual above `max_rms_mm` or a change from the nominal beyond `max_change_mm` /
 * `max_change_deg`, the calibration is refused, the nominal transform kept and the report says why.
 *
 * Every move goes over the top: the column rises to its top, the wrist turns there, then the column
 * lowers, so the hand never sweeps low over the table; the arm ends where it started. */
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/ArmBody.h>
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/Timeline.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <array>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** Section [dock_calibration] (all keys optional). */
struct DockCalibrationOptions
{
	bool enabled = false;  ///< needs the marker in the images (in the lab: [sim_arm] draw_arm)
	int poses = 8;                       ///< presenting poses tried
	int min_poses = 4;                   ///< sightings needed for a fit
	double column_above_table_mm = 300;  ///< the arm's links this far above the table top
	double spread_mm = 100;              ///< least distance between two presenting positions
	double max_rms_mm = 5;               ///< a worse fit is refused
	double max_change_mm = 80;           ///< a calibrated mount farther from the nominal is refused
	double max_change_deg = 8;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

struct DockCalibrationResult
{
	bool attempted = false;   ///< the arm presented the marker
	bool calibrated = false;  ///< T_C0inA is the fitted one
	std::string reason;       ///< why not, "" when calibrated
	int poses_planned = 0;    ///< poses in reach
	int sightings = 0;        ///< marker found in both images
	arm::MountFit fit;        ///< the fit (when at least three sightings)
	Eigen::Isometry3d T_C0inA = Eigen::Isometry3d::Identity();  ///< the transform used, mm
	double change_mm = 0, change_deg = 0;  ///< fitted against nominal
	std::vector<uint64_t> frames;          ///< the pairs the marker was sought in
	double time_s = 0;                     ///< simulated time of the arm and head moves
	double compute_s = 0;                  ///< robot compute (detection, triangulation, fit)
};

class DockCalibrator
{
 public:
	/** A stereo pair with the head moved to the given angles. */
	using Look = std::function<hw::StereoImages(const geometry::HeadAngles&)>;
	DockCalibrator(const DockCalibrationOptions& o, const arm::RtxOptions& rtx,
	               const arm::GraspFeasibilityOptions& grip, const arm::MarkerOptions& marker, const geometry::BiSightHead& head,
	               double arm_move_time_s, double head_move_time_s);

	/** Presents, sees and fits. @p T_C0inA_nominal: the configured mount (mm); @p p_OinC0_mm: the
	 * object the poses ring; @p table_z_in_A_mm: the table top's height in A. */
	DockCalibrationResult run(hw::ArmDevice& arm, const Look& look,
	                          const Eigen::Isometry3d& T_C0inA_nominal,
	                          const Eigen::Vector3d& p_OinC0_mm, double table_z_in_A_mm,
	                          Timeline& timeline) const;

	/** The presenting gripper poses (A, mm) with their joints: on a grid over the wrist's reach at
	 * two heights above the table, the hand pointing up and the marker's face turned towards the
	 * head as nearly as the wrist allows (IK), the marker within the head's joints and, by the
	 * arm's own body (arm/ArmBody.h), in view of both cameras; the nearest the object first, each
	 * at least spread_mm from the others, `poses` at most. */
	std::vector<std::pair<Eigen::Isometry3d, arm::RtxJoints>> presentingPoses(
	    const Eigen::Isometry3d& T_C0inA_nominal, const Eigen::Vector3d& p_OinC0_mm,
	    double table_z_in_A_mm) const;

 private:
	/** The marker at @p T_GinA fixatable, and no arm box (but the hand's) across its lines of
	 * sight from the cameras (head at zero angles). */
	bool markerInView(const arm::RtxJoints& j, const Eigen::Isometry3d& T_GinA,
	                  const Eigen::Isometry3d& T_AinC0) const;
	std::optional<arm::RtxJoints> facingHead(const Eigen::Vector3d& p_GinA_mm,
	                                         const Eigen::Vector2d& to_head_xy) const;
	/** Over the top: column up, the other joints turned, column down to @p j. */
	void moveOverTop(hw::ArmDevice& arm, const arm::RtxJoints& j, DockCalibrationResult& r) const;
	/** The marker's centre in C0 (mm) seen with the head fixating @p predicted_inC0_mm. */
	std::optional<Eigen::Vector3d> sight(const Look& look, const Eigen::Vector3d& predicted_inC0_mm,
	                                     DockCalibrationResult& r) const;
	void judge(DockCalibrationResult& r, const Eigen::Isometry3d& T_C0inA_nominal) const;

	DockCalibrationOptions o_;
	arm::RtxOptions rtx_;
	arm::MarkerOptions marker_;
	geometry::BiSightHead head_;
	arm::AnalyticIk ik_;
	arm::RtxKinematics kin_;
	std::vector<arm::BodyBox> body_;
	std::array<Eigen::Vector3d, 2> cameras_mm_;  ///< optic centres in C0 (mm)
	double arm_move_time_s_, head_move_time_s_;
};

}  // namespace mrolr::mission
