#pragma once
/** Trajectories in the TUM RGB-D benchmark's text format, one pose per line:
 * `timestamp tx ty tz qx qy qz qw` (seconds, metres, unit quaternion), as the SLAM community's
 * evaluation tools read it (evo: `evo_ape tum truth.tum estimate.tum`).
 *
 * A file is an edge of the project, so poses are in MRPT's axes (DESIGN.md "Frames"): the vehicle
 * state x_v = (z, x, φ) of the thesis (4.2.6) becomes x = z, y = x, z = 0 and a yaw φ about the
 * vertical (geometry::vehicleToMrpt). */
#include <Eigen/Core>

#include <string>
#include <vector>

namespace mrolr::io
{
/** A vehicle state (z, x, φ; m, m, rad, thesis 4.2.6) at a time (s). */
struct StampedVehicle
{
	double time_s = 0;
	Eigen::Vector3d xv_zxphi = Eigen::Vector3d::Zero();
};

/** One TUM line: `t x y z qx qy qz qw`, the time to the nanosecond, the rest to 12 significant
 * digits. */
std::string tumLine(const StampedVehicle& s);

/** Writes @p poses to @p path. Throws std::invalid_argument naming the row of a non-finite value
 * or a time that goes back, and std::runtime_error naming @p path when it cannot be written. */
void writeTum(const std::string& path, const std::vector<StampedVehicle>& poses);

/** Reads a TUM file back as vehicle states (the yaw of the quaternion; '#' lines are comments).
 * Throws std::runtime_error naming file and line for a malformed line or a pose that is not
 * planar (tilted, or off the floor by more than 1 µm). */
std::vector<StampedVehicle> readTum(const std::string& path);

}  // namespace mrolr::io
