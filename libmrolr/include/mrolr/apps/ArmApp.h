#pragma once
/** mrolr-arm: the UMI RTX arm's kinematics and grasp chain from the command line (thesis 6.6–6.7,
 * B.3). Commands:
 *   fk D1 Q1 Q2 Q3 Q4 Q5 Q6                     → T06 (mm, degrees in)
 *   ik X Y Z YAW PITCH ROLL | ik --pose P       → every solution within the limits, or the reason
 *   grasp --object-in-c0 P --grasp x,y,z,yaw,pitch,roll --mount parallel|45|FILE.ini
 *                                               → T_OinA, the grasp pose T_GinA and its IK
 *   calibrate --object-in-arm P --object-in-c0 P → T_C0inA (eq 6.7.2)
 * P is 12 comma-separated numbers, the rows of [R | t] in mm. Every command takes --json and
 * --config FILE (default config/arm_rtx.ini). Results are left in the public fields. */

#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/GripperPose.h>
#include <mrolr/arm/JacobianIk.h>
#include <mrolr/arm/RtxOptions.h>

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
class ArmApp
{
 public:
	/** Parses the full argv (argv[0] first, negative numbers protected). Throws util::UsageError
	 * for bad arguments; after --help, help_shown is set and run() does nothing. */
	void initialize(const std::vector<std::string>& args);

	/** Computes and prints the result; returns 0, or 1 when no IK solution exists. */
	int run();

	// --- parsed input ---
	std::string command;  ///< fk | ik | grasp | calibrate
	bool json = false;
	bool help_shown = false;
	bool use_jacobian = false;  ///< ik --jacobian: the DLS solver of B.3.3 from the home pose
	std::string config_path;
	std::string mount_spec;  ///< parallel | 45 | FILE.ini
	arm::RtxJoints fk_joints;
	Eigen::Isometry3d target = Eigen::Isometry3d::Identity();  ///< ik: requested T06
	Eigen::Isometry3d T_OinC0 = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d T_OinA_measured = Eigen::Isometry3d::Identity();  ///< calibrate input
	arm::GripperPose grasp_in_object;

	// --- results ---
	arm::RtxOptions rtx;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();       ///< the command's main matrix
	Eigen::Isometry3d T_GinA = Eigen::Isometry3d::Identity();  ///< grasp: gripper in A
	arm::IkResult ik;                                          ///< ik, grasp
	std::optional<arm::JacobianIkResult> jacobian;             ///< ik --jacobian
	nlohmann::json output;                                     ///< what --json prints

	std::ostream* out = &std::cout;

 private:
	void parseFk(const std::vector<std::string>& args);
	void parseIk(const std::vector<std::string>& args);
	void parseGrasp(const std::vector<std::string>& args);
	void parseCalibrate(const std::vector<std::string>& args);
	int runIk(const Eigen::Isometry3d& T06);
	void printText() const;
};

/** Resolves --mount: "parallel" and "45" name config/arm_mount_parallel.ini and
 * config/arm_mount_45.ini in the source tree; anything else is a file path. */
std::string armMountPath(const std::string& spec);

}  // namespace mrolr::apps
