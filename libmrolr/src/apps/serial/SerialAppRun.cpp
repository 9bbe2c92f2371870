#include <mrolr/apps/SerialApp.h>
#include <mrolr/hw_serial/SerialClient.h>
#include <mrolr/hw_serial/SerialPortTransport.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/sim/SimHead.h>

#include <mrpt/config/CConfigFile.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <thread>

namespace mrolr::apps
{
namespace
{
std::atomic<bool> g_interrupted{false};

void onSignal(int)
{
	g_interrupted = true;
}

mrpt::config::CConfigFile openConfig(const std::string& file)
{
	if (!std::ifstream(file)) throw std::runtime_error(file + ": cannot open the config file");
	return mrpt::config::CConfigFile(file);
}

/** The three simulated devices; the head renders an empty scene (its images are not served). */
struct SimDevices
{
	base::LabmateModel model;
	sim::SimBase base;
	geometry::BiSightHead bisight;
	sim::StereoRenderer renderer{bisight, sim::RenderOptions{}};
	mrpt::opengl::COpenGLScene scene;
	sim::SimHead head;
	std::map<std::string, Eigen::Isometry3d> objects;
	sim::SimArm arm;

	template <typename O>
	static O load(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
	{
		O o;
		o.loadFromConfigFile(cfg, section);
		return o;
	}
	SimDevices(const mrpt::config::CConfigFileBase& sim, const mrpt::config::CConfigFileBase& lab)
	    : model(load<base::LabmateOptions>(lab, "labmate")),
	      base(model, load<sim::SimBaseOptions>(sim, "sim_base")),
	      head(
	          renderer, scene, [] { return Eigen::Isometry3d::Identity(); },
	          load<sim::SimHeadOptions>(sim, "sim_head")),
	      arm([](const hw::ArmJoints&) { return Eigen::Isometry3d::Identity(); },
	          load<sim::SimArmOptions>(sim, "sim_arm"), objects)
	{
	}
};

bool keepRunning(double seconds, std::chrono::steady_clock::time_point start)
{
	if (g_interrupted) return false;
	if (seconds <= 0) return true;
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
	       seconds;
}
}  // namespace

int SerialApp::run()
{
	if (help_shown) return 0;
	return command == "emulate" ? runEmulate() : runSend();
}

int SerialApp::runEmulate()
{
	SimDevices sim(openConfig(sim_file), openConfig(labmate_file));
	hw::BaseHandler bh(sim.base);
	hw::HeadHandler hh(sim.head);
	hw::ArmHandler ah(sim.arm);
	hw::PtyEmulator eb(bh, faults), eh(hh, faults), ea(ah, faults);
	ports = {eb.slavePath(), eh.slavePath(), ea.slavePath()};
	if (json)
		std::cout << nlohmann::json{{"base", ports[0]}, {"head", ports[1]}, {"arm", ports[2]}}
		          << std::endl;
	else
		std::cout << "base " << ports[0] << "\nhead " << ports[1] << "\narm " << ports[2]
		          << std::endl;
	g_interrupted = false;
	std::signal(SIGINT, onSignal);
	std::signal(SIGTERM, onSignal);
	const auto start = std::chrono::steady_clock::now();
	while (keepRunning(seconds, start)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
	requests_served =
	    eb.emulator().executed() + eh.emulator().executed() + ea.emulator().executed();
	return 0;
}

int SerialApp::runSend()
{
	hw::LinkOptions link;
	link.device = "device";
	link.timeout_ms = timeout_ms;
	link.retries = retries;
	try
	{
		hw::SerialClient client(std::make_unique<hw::SerialPortTransport>(port, baud), link);
		reply = client.call(verb, fields);
	}
	catch (const std::exception& e)  // SerialDeviceError, or TransportClosed when opening
	{
		error = e.what();
	}
	if (json)
		std::cout << nlohmann::json{{"ok", error.empty()}, {"reply", reply}, {"error", error}}
		          << std::endl;
	else if (error.empty())
	{
		for (size_t i = 0; i < reply.size(); ++i) std::cout << (i ? " " : "") << reply[i];
		std::cout << (reply.empty() ? "OK\n" : "\n");
	}
	else
		std::cerr << "mrolr-serial: " << error << "\n";
	return error.empty() ? 0 : 1;
}

}  // namespace mrolr::apps
