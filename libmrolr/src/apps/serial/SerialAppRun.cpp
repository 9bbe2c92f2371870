#include <mrolr/apps/SerialApp.h>
#include <mrolr/apps/SerialEmulation.h>
#include <mrolr/apps/StopSignals.h>
#include <mrolr/apps/TruthRecording.h>
#include <mrolr/eval/MissionTruth.h>
#include <mrolr/hw_serial/SerialClient.h>
#include <mrolr/hw_serial/SerialPortTransport.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

namespace mrolr::apps
{
namespace
{

bool keepRunning(double seconds, std::chrono::steady_clock::time_point start,
                 const StopSignals& signals, StopSignals& flag)
{
	if (flag.flag() || signals.received()) return false;
	if (seconds <= 0) return true;
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
	       seconds;
}

/** T.json, and beside it T.rawlog with the true pose after every base step (GROUND_TRUTH). */
void writeTruth(const sim::Lab& lab, const std::string& path)
{
	std::ofstream out(path);
	out << eval::truthJson(eval::truthOf(lab)).dump(2) << "\n";
	if (!out) throw std::runtime_error(path + ": cannot write the truth");
	writeTruthRawlog(lab, (std::filesystem::path(path).replace_extension(".rawlog")).string());
}
}  // namespace

int SerialApp::run()
{
	if (help_shown) return 0;
	return command == "emulate" ? runEmulate() : runSend();
}

int SerialApp::runEmulate()
{
	const auto cfg = util::openConfigFile(sim_file);
	const auto dir = std::filesystem::path(sim_file).parent_path().string();
	sim::Lab lab(sim::LabOptions::load(cfg, dir, world_file));
	SerialEmulation emulation(lab, faults);
	ports = {emulation.base().slavePath(), emulation.head().slavePath(),
	         emulation.arm().slavePath(), emulation.camera().address()};
	if (json)
		std::cout << nlohmann::json{{"base", ports[0]}, {"head", ports[1]}, {"arm", ports[2]},
		                            {"camera", ports[3]}}
		          << std::endl;
	else
		std::cout << "base " << ports[0] << "\nhead " << ports[1] << "\narm " << ports[2]
		          << "\ncamera " << ports[3] << std::endl;
	StopSignals signals;
	const auto start = std::chrono::steady_clock::now();
	while (keepRunning(seconds, start, signals, signals))
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	requests_served = emulation.base().emulator().executed() +
	                  emulation.head().emulator().executed() +
	                  emulation.arm().emulator().executed();
	if (!truth_out.empty()) writeTruth(lab, truth_out);
	return 0;
}
int SerialApp::runSend()
{
	hw_serial::LinkOptions link;
	link.device = "device";
	link.timeout_ms = timeout_ms;
	link.retries = retries;
	try
	{
		hw_serial::SerialClient client(std::make_unique<hw_serial::SerialPortTransport>(port, baud), link);
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
