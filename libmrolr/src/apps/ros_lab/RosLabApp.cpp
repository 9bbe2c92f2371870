// mrolr-ros-lab: the simulated lab on the device topics (RosLabApp.h).
#include <mrolr/apps/RosLabApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/apps/TruthRecording.h>
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceServer.h>
#include <mrolr/ros/DeviceTopics.h>
#include <mrolr/ros/Node.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

#include <filesystem>
#include <fstream>
#include <ostream>

namespace mrolr::apps
{
void RosLabApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-ros-lab: the simulated lab's devices on ROS 1 topics (docs/ros.md)",
	                   ' ', "1");
	TCLAP::ValueArg<std::string> cfg("", "config",
	                                 "mission .ini with the simulator's sections (default "
	                                 "config/mission_sim.ini)",
	                                 false, config_path, "FILE", cmd);
	TCLAP::ValueArg<std::string> world("", "world", "the world (default [simulator] world_file)",
	                                   false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> truth(
	    "", "truth", "at the end, write the true pose after every base step here (a rawlog)", false,
	    "", "FILE", cmd);
	TCLAP::ValueArg<int> wait("", "master-timeout-ms", "wait this long for the ROS master", false,
	                          master_timeout_ms, "N", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	config_path = util::projectFile(cfg.getValue());
	world_path = world.getValue();
	truth_path = truth.getValue();
	master_timeout_ms = wait.getValue();
	if (master_timeout_ms < 0) throw util::UsageError("--master-timeout-ms must not be negative");
}

namespace
{
/** The lab's truth after a step: the true vehicle pose in `world` (REP 105), never read by the
 * robot. */
geometry_msgs::PoseStamped truthMsg(const sim::Lab& lab, double time_s)
{
	geometry_msgs::PoseStamped p;
	p.header.stamp = ros::toRosTime(time_s);
	p.header.frame_id = "world";
	p.pose = ros::toPoseMsg(ros::planarPose(lab.truePose()));
	return p;
}
}  // namespace

int RosLabApp::run(std::ostream& out)
{
	if (help_shown) return 0;
	if (!std::ifstream(config_path))
		throw util::ConfigError(config_path + ": cannot open the mission configuration");
	const auto cfg = util::openConfigFile(config_path);
	sim::Lab lab(sim::LabOptions::load(
	    cfg, std::filesystem::path(config_path).parent_path().string(), world_path));
	ros::waitForMaster(master_timeout_ms);
	::ros::NodeHandle nh;
	ros::DeviceServer server(nh, {&lab.base(), &lab.head(), &lab.arm()});
	auto truth = nh.advertise<geometry_msgs::PoseStamped>(ros::topics::kTruthPose,
	                                                      ros::topics::kPublisherQueue, true);
	truth.publish(truthMsg(lab, lab.base().odometry().time_s));
	server.after_step = [&](double t) { truth.publish(truthMsg(lab, t)); };
	const auto camera = geometry::BiSightHead(lab.options().bisight).camera().toTCamera();
	server.after_grab = [&,
	                     left = nh.advertise<sensor_msgs::CameraInfo>(ros::topics::kLeftInfo,
	                                                                  ros::topics::kPublisherQueue),
	                     right = nh.advertise<sensor_msgs::CameraInfo>(
	                         ros::topics::kRightInfo, ros::topics::kPublisherQueue)](double t)
	{
		left.publish(ros::toCameraInfo(camera, t, "left_camera"));
		right.publish(ros::toCameraInfo(camera, t, "right_camera"));
	};
	out << "mrolr-ros-lab: serving the lab of " << lab.options().world_file << " as "
	    << ::ros::this_node::getName() << " on " << ::ros::master::getURI() << std::endl;
	::ros::spin();  // one thread: the devices run in the order the robot asks
	commands = server.commands();
	if (!truth_path.empty()) writeTruthRawlog(lab, truth_path);
	out << "mrolr-ros-lab: served " << commands << " commands"
	    << (truth_path.empty() ? "" : "; truth in " + truth_path) << std::endl;
	return 0;
}

}  // namespace mrolr::apps
