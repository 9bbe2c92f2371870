// mrolr-ros-robot: the mission on the device topics (RosRobotApp.h).
#include "RobotView.h"

#include <mrolr/apps/MissionSummary.h>
#include <mrolr/apps/RosRobotApp.h>
#include <mrolr/apps/RunConfiguration.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/mission/DeviceRecorder.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/ros/Node.h>
#include <mrolr/ros/RosDevices.h>
#include <mrolr/util/Config.h>

#include <ros/ros.h>

#include <atomic>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <thread>

namespace mrolr::apps
{
void RosRobotApp::initialize(const std::vector<std::string>& args)
{
	command = args;
	TCLAP::CmdLine cmd(
	    "mrolr-ros-robot: the fetch mission on ROS 1 device topics (docs/ros.md); the devices are "
	    "served by mrolr-ros-lab or real drivers",
	    ' ', "1");
	TCLAP::ValueArg<std::string> cfg("", "config", "mission .ini (default config/mission_sim.ini)",
	                                 false, config_path, "FILE", cmd);
	TCLAP::ValueArg<std::string> plan("", "plan", "the robot's plan (default [mission] plan)",
	                                  false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "output folder (default out/<name>-ros-<timestamp>)",
	                                 false, "", "DIR", cmd);
	TCLAP::SwitchArg js("", "json", "print report.json instead of the summary", cmd);
	TCLAP::SwitchArg q("", "quiet", "no progress line", cmd);
	TCLAP::ValueArg<int> timeout("", "timeout-ms",
	                             "a device reply later than this (beyond the command's own "
	                             "duration) stops the mission",
	                             false, timeout_ms, "N", cmd);
	TCLAP::ValueArg<int> motion("", "motion-timeout-ms",
	                            "a head or arm move or a stereo grab answered later than this stops "
	                            "the mission",
	                            false, motion_timeout_ms, "N", cmd);
	TCLAP::ValueArg<int> lab("", "lab-timeout-ms", "wait this long for the lab's topics at start",
	                         false, lab_timeout_ms, "N", cmd);
	TCLAP::ValueArg<int> wait("", "master-timeout-ms", "wait this long for the ROS master", false,
	                          master_timeout_ms, "N", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	config_path = util::projectFile(cfg.getValue());
	plan_path = plan.getValue();
	out_dir = out.getValue();
	json = js.getValue();
	quiet = q.getValue();
	timeout_ms = timeout.getValue();
	motion_timeout_ms = motion.getValue();
	lab_timeout_ms = lab.getValue();
	master_timeout_ms = wait.getValue();
	for (const auto& [name, v] :
	     {std::pair{"--timeout-ms", timeout_ms}, {"--motion-timeout-ms", motion_timeout_ms},
	      {"--lab-timeout-ms", lab_timeout_ms},
	      {"--master-timeout-ms", master_timeout_ms}})
		if (v <= 0) throw util::UsageError(std::string(name) + " must be positive");
}

namespace
{
/** The robot over ROS has its cameras and nothing else: no simulator's shortcut sensors. */
void requireDeviceSensors(const mission::MissionOptions& o)
{
	if (o.navigation.landmark_source == mission::LandmarkSource::Simulated)
		throw util::ConfigError(o.config_path +
		                        " [navigation] landmark_source = simulated: the robot over ROS "
		                        "measures landmarks from its images only");
	if (o.search.scene_source == mission::SceneSource::Simulated)
		throw util::ConfigError(o.config_path +
		                        " [search] scene_source = simulated: the robot over ROS "
		                        "reconstructs scenes from its images only");
}

/** Stops the mission safely on SIGINT / SIGTERM (ros/Node.h only records them: the topics stay
 * up to send the stop). */
struct ShutdownWatch
{
	std::atomic<bool> flag{false};
	std::atomic<bool> done{false};
	std::thread watcher{[this]
	                    {
		                    while (!done)
		                    {
			                    if (ros::shutdownSignal()) flag = true;
			                    std::this_thread::sleep_for(std::chrono::milliseconds(20));
		                    }
	                    }};
	~ShutdownWatch()
	{
		done = true;
		watcher.join();
	}
};
}  // namespace

int RosRobotApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	options = mission::MissionOptions::load(config_path, {plan_path, {}});
	options.config_path = config_path;
	requireDeviceSensors(options);
	ros::waitForMaster(master_timeout_ms);
	::ros::NodeHandle nh;
	ros::RosDeviceOptions ro;
	ro.timeout_ms = timeout_ms;
	ro.motion_timeout_ms = motion_timeout_ms;
	ro.connect_timeout_ms = lab_timeout_ms;
	ros::RosDevices devices(nh, ro);  // waits for the lab; hw::DeviceFailure names what is missing
	if (out_dir.empty()) out_dir = "out/" + options.name + "-ros-" + utcStamp();
	std::filesystem::create_directories(out_dir);
	writeRunConfiguration({config_path, {}, "", command}, options, out_dir);  // for --replay
	const std::string rawlog = (std::filesystem::path(out_dir) / "mission.rawlog").string();
	const geometry::BiSightHead head(options.bisight);
	// the views see the devices' own answers; the recorder records only the mission's calls
	RobotView view(nh, head, options.rtx, options.dock);
	ViewedHead viewed_head(devices.head, view);
	ViewedArm viewed_arm(devices.arm, view);
	mission::DeviceRecorder recorder(rawlog, {&devices.base, &viewed_head, &viewed_arm, {}}, head);
	view.next = &recorder;
	const auto recorded = recorder.devices();
	ShutdownWatch signals;
	mission::Mission m(options, recorded);
	if (!quiet) summary::attachProgress(m, progress);
	m.stop_flag = &recorder.stopFlag(&signals.flag);
	m.decisions = &view;
	result = m.run();
	recorder.flush();
	if (!quiet) progress << "\n";
	view.finished(result);
	report = mission::reportJson(result, options);
	report["transport"] = "ros";
	report["ros_master"] = ::ros::master::getURI();
	const auto dir = std::filesystem::path(out_dir);
	std::ofstream(dir / "report.json") << report.dump(2) << "\n";
	std::ofstream(dir / "report.md") << mission::reportMarkdown(report);
	if (json)
		out << report.dump(2) << "\n";
	else
		summary::printSummary(out, report, out_dir);
	::ros::WallDuration(0.3).sleep();  // the latched map and stage reach a recorder still up
	if (const int sig = ros::shutdownSignal()) return 128 + sig;
	return report["success"].get<bool>() ? 0 : 3;
}

}  // namespace mrolr::apps
