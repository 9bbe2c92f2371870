#include <mrolr/apps/ArmApp.h>
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/util/Cli.h>

#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <iomanip>

namespace mrolr::apps
{
namespace
{
/** Prints −0 and rounding residue below 1e-12 as 0. */
double tidy(double v)
{
	return std::abs(v) < 1e-12 ? 0.0 : v;
}

nlohmann::json matrixJson(const Eigen::Isometry3d& T)
{
	nlohmann::json rows = nlohmann::json::array();
	for (int r = 0; r < 4; ++r)
	{
		nlohmann::json row = nlohmann::json::array();
		for (int c = 0; c < 4; ++c) row.push_back(tidy(T.matrix()(r, c)));
		rows.push_back(row);
	}
	return rows;
}

nlohmann::json gripperJson(const Eigen::Isometry3d& T)
{
	const arm::GripperPose g = arm::gripperFromPose(T);
	return {{"x_mm", tidy(g.p_mm.x())},       {"y_mm", tidy(g.p_mm.y())},
	        {"z_mm", tidy(g.p_mm.z())},       {"yaw_deg", tidy(g.yaw_deg)},
	        {"pitch_deg", tidy(g.pitch_deg)}, {"roll_deg", tidy(g.roll_deg)}};
}

nlohmann::json jointsJson(const arm::RtxJoints& j)
{
	const auto v = j.toMmDeg();
	return nlohmann::json(std::vector<double>(v.begin(), v.end()));
}

nlohmann::json solutionsJson(const arm::IkResult& ik)
{
	nlohmann::json list = nlohmann::json::array();
	for (const auto& s : ik.solutions)
	{
		const auto c = arm::roundCounts(s.counts);
		list.push_back({{"joints", jointsJson(s.joints)},
		                {"counts", std::vector<long>(c.begin(), c.end())},
		                {"elbow", s.elbow_left ? "left" : "right"},
		                {"wrist", s.wrist_flipped ? "flipped" : "normal"}});
	}
	return list;
}

void printMatrix(std::ostream& out, const std::string& name, const Eigen::Isometry3d& T)
{
	out << name << " =\n";
	for (int r = 0; r < 4; ++r)
	{
		for (int c = 0; c < 4; ++c)
			out << std::setw(12) << std::fixed << std::setprecision(4) << tidy(T.matrix()(r, c));
		out << "\n";
	}
}

void printSolutions(std::ostream& out, const arm::IkResult& ik)
{
	if (ik.solutions.empty())
	{
		out << "no solution: " << ik.reason() << "\n";
		return;
	}
	out << ik.solutions.size()
	    << " solution(s): d1_mm q1..q6_deg | counts column shoulder elbow "
	       "yaw wrist1 wrist2\n";
	for (const auto& s : ik.solutions)
	{
		out << "  " << (s.elbow_left ? "elbow left " : "elbow right")
		    << (s.wrist_flipped ? " wrist flipped:" : " wrist normal: ");
		for (double v : s.joints.toMmDeg()) out << " " << std::setprecision(4) << v;
		out << " |";
		for (long c : arm::roundCounts(s.counts)) out << " " << c;
		out << "\n";
	}
}
}  // namespace

int ArmApp::runIk(const Eigen::Isometry3d& T06)
{
	ik = arm::AnalyticIk(rtx).solve(T06);
	output["solutions"] = solutionsJson(ik);
	if (ik.solutions.empty()) output["reason"] = ik.reason();
	return ik.solutions.empty() ? util::kExitFailure : util::kExitOk;
}

int ArmApp::run()
{
	if (help_shown) return util::kExitOk;
	rtx = arm::RtxOptions::fromFile(config_path);
	output = nlohmann::json::object();
	int code = util::kExitOk;
	if (command == "fk")
	{
		T = arm::RtxKinematics(rtx).T06(fk_joints);
		const auto c = arm::roundCounts(arm::jointsToCounts(fk_joints, rtx));
		output["joints"] = jointsJson(fk_joints);
		output["counts"] = std::vector<long>(c.begin(), c.end());
		const std::string limit = arm::limitViolation(arm::jointsToCounts(fk_joints, rtx), rtx);
		if (!limit.empty()) output["limit_violation"] = limit;
	}
	else if (command == "ik")
	{
		T = target;
		code = runIk(target);
		if (use_jacobian)
		{
			mrpt::config::CConfigFile cfg(config_path);
			arm::JacobianIkOptions jo;
			jo.loadFromConfigFile(cfg, "rtx_jacobian_ik");
			jacobian = arm::JacobianIk(rtx, jo).solve(target, arm::RtxJoints());
			output["jacobian"] = {{"converged", jacobian->converged},
			                      {"iterations", jacobian->iterations},
			                      {"joints", jointsJson(jacobian->joints)},
			                      {"position_error_mm", jacobian->position_error_mm},
			                      {"orientation_error_rad", jacobian->orientation_error_rad}};
		}
	}
	else if (command == "grasp")
	{
		const arm::ArmMount mount = arm::ArmMount::fromFile(armMountPath(mount_spec));
		T = arm::objectInArm(mount.T_C0inA, T_OinC0);
		T_GinA = T * arm::poseFromGripper(grasp_in_object);
		output["T_OinA"] = matrixJson(T);
		output["T_GinA"] = matrixJson(T_GinA);
		output["T_C0inA"] = matrixJson(mount.T_C0inA);
		code = runIk(T_GinA);
	}
	else  // calibrate
	{
		T = arm::calibrateHeadInArm(T_OinA_measured, T_OinC0);
		output["T_AinC0"] = matrixJson(T.inverse(Eigen::Isometry));
	}
	output["T"] = matrixJson(T);
	if (command == "fk" || command == "ik") output["gripper"] = gripperJson(T);
	if (command == "grasp") output["gripper"] = gripperJson(T_GinA);
	if (json)
		*out << output.dump(2) << "\n";
	else
		printText();
	return code;
}

void ArmApp::printText() const
{
	auto& o = *out;
	const char* names[] = {"T06", "T06 (requested)", "T_OinA", "T_C0inA"};
	const int k = command == "fk" ? 0 : command == "ik" ? 1 : command == "grasp" ? 2 : 3;
	printMatrix(o, names[k], T);
	if (command == "calibrate") printMatrix(o, "T_AinC0", T.inverse(Eigen::Isometry));
	if (command == "grasp") printMatrix(o, "T_GinA (gripper at the grasp)", T_GinA);
	if (output.contains("gripper"))
	{
		const auto& g = output["gripper"];
		o << "gripper: x y z = " << g["x_mm"].get<double>() << " " << g["y_mm"].get<double>() << " "
		  << g["z_mm"].get<double>() << " mm, yaw pitch roll = " << g["yaw_deg"].get<double>()
		  << " " << g["pitch_deg"].get<double>() << " " << g["roll_deg"].get<double>() << " deg\n";
	}
	if (command == "fk")
	{
		o << "counts (column shoulder elbow yaw wrist1 wrist2):";
		for (long c : output["counts"]) o << " " << c;
		o << "\n";
		if (output.contains("limit_violation"))
			o << "warning: " << output["limit_violation"].get<std::string>() << "\n";
	}
	if (command == "ik" || command == "grasp") printSolutions(o, ik);
	if (jacobian)
		o << "jacobian IK (B.3.3) from the initial configuration: "
		  << (jacobian->converged ? "converged" : "did not converge") << " in "
		  << jacobian->iterations << " iterations, error " << jacobian->position_error_mm << " mm, "
		  << jacobian->orientation_error_rad << " rad\n";
}

}  // namespace mrolr::apps
