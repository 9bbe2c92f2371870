#include <mrolr/apps/ArmApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/PoseText.h>
#include <mrolr/util/Cli.h>

namespace mrolr::apps
{
namespace
{
const char* kConventions =
    "Frames and units: A is the arm base (z up the column axis, x along the arm at q1=q2=q3=0); "
    "lengths in mm, angles in degrees. A pose P is 12 comma-separated numbers, the rows of the "
    "3x4 matrix [R | t]: r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz. YAW, PITCH, ROLL give the "
    "gripper's orientation: its approach axis z_G = (cos yaw cos pitch, sin yaw cos pitch, "
    "-sin pitch), i.e. yaw is the heading from x towards y and pitch the angle below horizontal "
    "(90 = straight down); at roll 0 the gripper's x axis lies in the vertical plane through z_G "
    "on "
    "the upper side and its fingers close along the horizontal y_G = z_G x x_G; roll turns about "
    "z_G. R = Rz(yaw) Ry(90+pitch) Rz(180+roll); with q1 = 0: yaw = q2+q3+q4, pitch = 90-q5, "
    "roll = q6.";

Eigen::Isometry3d poseArg(const std::string& text, const std::string& what)
{
	try
	{
		return arm::parsePose12(text, what);
	}
	catch (const arm::PoseInputError& e)
	{
		throw util::UsageError(e.what());
	}
}

/** The options every command shares. */
struct Common
{
	TCLAP::SwitchArg json{"", "json", "print the result as JSON"};
	TCLAP::ValueArg<std::string> config{"",
	                                    "config",
	                                    "RTX parameters (.ini, section [rtx])",
	                                    false,
	                                    MROLR_SOURCE_DIR "/config/arm_rtx.ini",
	                                    "FILE"};
	void add(TCLAP::CmdLine& cmd)
	{
		cmd.add(json);
		cmd.add(config);
	}
};

void printTopHelp(std::ostream& out)
{
	out << "mrolr-arm: kinematics and grasp chain of the UMI RTX arm (thesis 6.6-6.7, B.3)\n\n"
	       "  mrolr-arm fk D1 Q1 Q2 Q3 Q4 Q5 Q6            forward kinematics -> T06\n"
	       "  mrolr-arm ik X Y Z YAW PITCH ROLL             every IK solution (or the reason "
	       "none)\n"
	       "  mrolr-arm ik --pose P [--jacobian]\n"
	       "  mrolr-arm grasp --object-in-c0 P --grasp x,y,z,yaw,pitch,roll --mount "
	       "parallel|45|FILE\n"
	       "  mrolr-arm calibrate --object-in-arm P --object-in-c0 P   -> T_C0inA (eq 6.7.2)\n\n"
	       "Every command takes --json and --config FILE; `mrolr-arm COMMAND --help` for "
	       "details.\n\n"
	    << kConventions << "\n";
}
}  // namespace

std::string armMountPath(const std::string& spec)
{
	if (spec == "parallel") return MROLR_SOURCE_DIR "/config/arm_mount_parallel.ini";
	if (spec == "45") return MROLR_SOURCE_DIR "/config/arm_mount_45.ini";
	return spec;
}

void ArmApp::initialize(const std::vector<std::string>& args)
{
	if (args.size() < 2) throw util::UsageError("missing command (fk, ik, grasp or calibrate)");
	command = args[1];
	if (command == "--help" || command == "-h")
	{
		printTopHelp(*out);
		help_shown = true;
		return;
	}
	std::vector<std::string> rest = {"mrolr-arm " + command};
	rest.insert(rest.end(), args.begin() + 2, args.end());
	if (command == "fk")
		parseFk(rest);
	else if (command == "ik")
		parseIk(rest);
	else if (command == "grasp")
		parseGrasp(rest);
	else if (command == "calibrate")
		parseCalibrate(rest);
	else
		throw util::UsageError("unknown command '" + command + "' (fk, ik, grasp or calibrate)");
}

void ArmApp::parseFk(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    std::string("Forward kinematics: the 4x4 T06 of the gripper in the arm base "
	                "for column height D1 (mm) and joint angles Q1..Q6 (degrees). ") +
	        kConventions,
	    ' ', "", true);
	Common common;
	TCLAP::UnlabeledMultiArg<std::string> values("values", "D1 Q1 Q2 Q3 Q4 Q5 Q6", true, "NUMBER");
	cmd.add(values);
	common.add(cmd);
	if ((help_shown = !parseTclap(cmd, args))) return;
	if (values.getValue().size() != 7)
		throw util::UsageError("fk: expected 7 numbers D1 Q1 Q2 Q3 Q4 Q5 Q6, got " +
		                       std::to_string(values.getValue().size()));
	std::array<double, 7> v{};
	const char* names[] = {"D1", "Q1", "Q2", "Q3", "Q4", "Q5", "Q6"};
	for (size_t i = 0; i < 7; ++i) v[i] = util::parseNumberArg(values.getValue()[i], names[i]);
	fk_joints = arm::RtxJoints::fromMmDeg(v);
	json = common.json.getValue();
	config_path = common.config.getValue();
}

void ArmApp::parseIk(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    std::string("Inverse kinematics: every joint solution within the limits that "
	                "puts the gripper at X Y Z (mm) with YAW PITCH ROLL (degrees), or "
	                "at the pose P; with joint values and motor encoder counts. ") +
	        kConventions,
	    ' ', "", true);
	Common common;
	TCLAP::UnlabeledMultiArg<std::string> values("values", "X Y Z YAW PITCH ROLL", false, "NUMBER");
	TCLAP::ValueArg<std::string> pose("", "pose", "gripper pose T06 as 12 numbers", false, "", "P");
	TCLAP::SwitchArg jac("", "jacobian",
	                     "also run the damped least-squares Jacobian solver of B.3.3 from the "
	                     "initial configuration");
	cmd.add(values);
	cmd.add(pose);
	cmd.add(jac);
	common.add(cmd);
	if ((help_shown = !parseTclap(cmd, args))) return;
	const auto& v = values.getValue();
	if (pose.isSet() == !v.empty())
		throw util::UsageError("ik: give either X Y Z YAW PITCH ROLL or --pose P");
	if (pose.isSet())
		target = poseArg(pose.getValue(), "--pose");
	else
	{
		if (v.size() != 6)
			throw util::UsageError("ik: expected 6 numbers X Y Z YAW PITCH ROLL, got " +
			                       std::to_string(v.size()));
		const char* names[] = {"X", "Y", "Z", "YAW", "PITCH", "ROLL"};
		double n[6];
		for (size_t i = 0; i < 6; ++i) n[i] = util::parseNumberArg(v[i], names[i]);
		target = arm::poseFromGripper({{n[0], n[1], n[2]}, n[3], n[4], n[5]});
	}
	use_jacobian = jac.getValue();
	json = common.json.getValue();
	config_path = common.config.getValue();
}

void ArmApp::parseGrasp(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    std::string("Grasp chain (thesis 6.6-6.7): T_OinA = T_C0inA * T_OinC0 for the "
	                "object pose in the head centre frame C0, the gripper pose of the "
	                "model's grasp line (in the object frame) and its IK solutions. ") +
	        kConventions,
	    ' ', "", true);
	Common common;
	TCLAP::ValueArg<std::string> obj("", "object-in-c0", "T_OinC0, 12 numbers", true, "", "P");
	TCLAP::ValueArg<std::string> grasp("", "grasp", "grasp line x,y,z,yaw,pitch,roll in O", true,
	                                   "", "x,y,z,yaw,pitch,roll");
	TCLAP::ValueArg<std::string> mount(
	    "", "mount", "arm mounting: parallel, 45, or an .ini file with [arm_mount] T_C0inA", true,
	    "", "M");
	cmd.add(obj);
	cmd.add(grasp);
	cmd.add(mount);
	common.add(cmd);
	if ((help_shown = !parseTclap(cmd, args))) return;
	T_OinC0 = poseArg(obj.getValue(), "--object-in-c0");
	try
	{
		grasp_in_object = arm::parseGripper(grasp.getValue(), "--grasp");
	}
	catch (const arm::PoseInputError& e)
	{
		throw util::UsageError(e.what());
	}
	mount_spec = mount.getValue();
	json = common.json.getValue();
	config_path = common.config.getValue();
}

void ArmApp::parseCalibrate(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(std::string("Calibration of the mounting (eq 6.7.2): T_C0inA = T_OinA * "
	                               "inverse(T_OinC0) from a test object's pose in the arm base and "
	                               "in the head centre frame. ") +
	                       kConventions,
	                   ' ', "", true);
	Common common;
	TCLAP::ValueArg<std::string> in_arm("", "object-in-arm", "T_OinA, 12 numbers", true, "", "P");
	TCLAP::ValueArg<std::string> in_c0("", "object-in-c0", "T_OinC0, 12 numbers", true, "", "P");
	cmd.add(in_arm);
	cmd.add(in_c0);
	common.add(cmd);
	if ((help_shown = !parseTclap(cmd, args))) return;
	T_OinA_measured = poseArg(in_arm.getValue(), "--object-in-arm");
	T_OinC0 = poseArg(in_c0.getValue(), "--object-in-c0");
	json = common.json.getValue();
	config_path = common.config.getValue();
}

}  // namespace mrolr::apps
