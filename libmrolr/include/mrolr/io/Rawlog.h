#pragma once
/** Recording of a robot run as an MRPT rawlog (actions + sensory frames), readable by rawlog-edit
 * and RawLogViewer, with the stereo images stored as external PNG files in `<name>_Images/`.
 *
 * One record becomes one (CActionCollection, CSensoryFrame) pair:
 *  - CActionRobotMovement2D (label "ODOMETRY"): the odometry increment since the previous record;
 *  - CObservationOdometry ("ODOMETRY"): the odometry pose (MRPT axes: x = thesis z, y = thesis x)
 *    and the encoder counts (encoderRightTicks = wheel 1, encoderLeftTicks = wheel 2);
 *  - CObservationStereoImages ("BISIGHT"): both images, both TCamera, cameraPose = left camera
 *    (x right, y down, z forward) on the vehicle (MRPT axes, origin on the ground under C0),
 *    rightCameraPose = right camera relative to the left;
 *  - CObservationRawDAQ ("HEAD_ANGLES"): AIN_double = {pan, tilt, verg_left, verg_right} in rad;
 *  - CObservationRobotPose ("GROUND_TRUTH"): the true vehicle pose (x = z, y = x, yaw = φ), only
 *    in records that carry it (written by the world side; a robot alone has no truth).
 * Every observation carries the timestamp 1.7e9 s + time_s (MRPT rejects timestamp 0). */

#include <mrpt/core/Clock.h>
#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::io
{
/** A run's time t (s) is stored as the timestamp 1.7e9 s + t: MRPT rejects timestamp 0. */
inline constexpr double kTimeOffset_s = 1.7e9;
inline mrpt::Clock::time_point stampOf(double time_s)
{
	return mrpt::Clock::fromDouble(kTimeOffset_s + time_s);
}
inline double timeOf(mrpt::Clock::time_point stamp)
{
	return mrpt::Clock::toDouble(stamp) - kTimeOffset_s;
}

/** One time step of a run. Angles in radians; poses (z, x, φ) in W. */
struct RawlogRecord
{
	double time_s = 0;
	Eigen::Vector3d odometry_zxphi = Eigen::Vector3d::Zero();
	long ticks_right = 0, ticks_left = 0;
	std::optional<Eigen::Vector3d> true_zxphi;  ///< the world side's truth, when it is known
	/** The robot's estimate after this odometry reading's step, with its covariance P_vv (a
	 * mission's recording: its `ESTIMATE`). */
	std::optional<Eigen::Vector3d> estimate_zxphi;
	Eigen::Matrix3d estimate_P = Eigen::Matrix3d::Zero();
	Eigen::Vector4d head_rad = Eigen::Vector4d::Zero();  ///< pan, tilt, verg_left, verg_right
	bool has_stereo = false;
	mrpt::img::CImage left, right;  ///< 8-bit greyscale (empty when read with ImageLoading::Paths)
	std::string left_file, right_file;  ///< the external images' paths (ImageLoading::Paths)
	mrpt::img::TCamera camera;      ///< intrinsics of both cameras
	Eigen::Isometry3d T_LcvInVehicle = Eigen::Isometry3d::Identity();  ///< MRPT axes vehicle
	Eigen::Isometry3d T_RcvInLcv = Eigen::Isometry3d::Identity();  ///< right cv cam in left cv cam
};

/** Writes records to a rawlog file; images go to `<stem>_Images/` next to it. */
class RawlogWriter
{
 public:
	/** Opens @p path for writing (throws std::runtime_error naming the path on failure). */
	explicit RawlogWriter(const std::string& path);
	~RawlogWriter();
	void write(const RawlogRecord& r);
	/** Number of records written. */
	size_t count() const { return count_; }
	const std::string& imagesDir() const { return images_dir_; }

 private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
	std::string images_dir_;
	size_t count_ = 0;
	Eigen::Vector3d last_odometry_ = Eigen::Vector3d::Zero();
};

/** Whether readRawlog loads the pairs' images, or only names their files (for a reader that
 * takes one pair at a time, so that a long recording does not have to fit in memory). */
enum class ImageLoading
{
	Load,
	Paths
};

/** Reads every record of a rawlog written by RawlogWriter, images loaded into memory (or only
 * their files named, with ImageLoading::Paths). A
 * mission's recording (observations-only, ObservationLog.h) reads as one record per odometry
 * reading and one per stereo pair, up to its last whole record. Throws std::runtime_error naming
 * the file and the record for anything unexpected. */
std::vector<RawlogRecord> readRawlog(const std::string& path,
                                     ImageLoading images = ImageLoading::Load);

/** The external images folder MRPT expects for @p rawlog_path: `<dir>/<stem>_Images`. */
std::string imagesDirFor(const std::string& rawlog_path);

}  // namespace mrolr::io
