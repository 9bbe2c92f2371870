#pragma once
/** The head-to-arm transform from a marker the arm presents (thesis 6.7, eq 6.7.2, over several
 * poses). The thesis measured T_C0inA once with a test object guided into the gripper by hand:
 * T_C0inA = T_OinA · (T_OinC0)⁻¹. Here the arm itself presents its hand's calibration marker (an
 * ArUco square on a stalk of the hand, [arm_marker]) at N known arm poses; the head triangulates
 * the square's centre each time, which gives N point pairs (p_MinA from the forward kinematics,
 * p_MinC0 from the stereo head), and T_C0inA is their least-squares rigid fit (Umeyama 1991,
 * Eigen::umeyama):
 *   T_C0inA = argmin Σ_k ‖ p_MinA,k − T · p_MinC0,k ‖².
 * One pose of a point gives no rotation; three poses not on one line give the whole transform. */

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::arm
{
/** The calibration marker on the hand: section [arm_marker] of the arm file (config/arm_rtx.ini),
 * an ArUco marker of OpenCV's DICT_4X4_50 on a square plate whose normal is +x_G. Both the robot
 * (to predict and to fit) and the simulator (to draw it) read it, as they read the arm's lengths. */
struct MarkerOptions
{
	Eigen::Vector3d p_MinG_mm{60, 0, -50};  ///< the marker square's centre in the gripper frame G
	double side_mm = 40;                      ///< side of the black square (the code's outer edge)
	int aruco_id = 7;                         ///< its id in DICT_4X4_50
	/** Half the plate's side: the code (6 cells) inside a one-cell white quiet zone (8 cells). */
	double plateHalfMm() const { return side_mm * 8.0 / 6.0 / 2.0; }

	/** Every key required; throws util::ConfigError naming the key. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The rigid fit of eq 6.7.2 over marker positions. */
struct MountFit
{
	Eigen::Isometry3d T_C0inA = Eigen::Isometry3d::Identity();  ///< mm
	double rms_mm = 0;      ///< residual ‖p_MinA − T_C0inA · p_MinC0‖, root mean square
	double max_mm = 0;      ///< the largest residual
	size_t points = 0;
};

/** Least-squares T_C0inA from pairs (p_MinA[k], p_MinC0[k]), mm. Throws std::invalid_argument when
 * the lists differ in length, hold fewer than three points, or the points in C0 lie on one line
 * (the rotation about it is then unobservable). */
MountFit fitHeadInArm(const std::vector<Eigen::Vector3d>& p_MinA_mm,
                      const std::vector<Eigen::Vector3d>& p_MinC0_mm);

}  // namespace mrolr::arm
