// The whole set of a run's outputs but its recording (mission/DeviceRecorder.h writes that).
#include <mrolr/eval/MissionEval.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/TumTrajectory.h>
#include <mrolr/mission/MissionOutputs.h>

#include <filesystem>
#include <fstream>

namespace mrolr::eval
{
WrittenOutputs writeMissionOutputs(const mission::MissionResult& r,
                                   const mission::MissionOptions& o, const MissionTruth* truth,
                                   const std::string& dir)
{
	std::filesystem::create_directories(dir);
	const auto f = [&](const std::string& n) { return (std::filesystem::path(dir) / n).string(); };
	WrittenOutputs out;
	out.report = mission::reportJson(r, o);
	if (truth) evaluateMission(out.report, *truth);
	std::ofstream(f("report.json")) << out.report.dump(2) << "\n";
	std::ofstream(f("report.md")) << mission::reportMarkdown(out.report);
	writeTrajectoryPng(r, o, truth, f("trajectory.png"));
	writeScene3D(r, o, truth, f("mission.3Dscene"));
	out.files = {f("report.json"), f("report.md"), f("trajectory.png"), f("mission.3Dscene")};
	for (const auto& tum : writeTumTrajectories(r, truth, dir)) out.files.push_back(tum);
	return out;
}

std::vector<std::string> writeTumTrajectories(const mission::MissionResult& r,
                                              const MissionTruth* truth, const std::string& dir)
{
	const auto f = [&](const std::string& n) { return (std::filesystem::path(dir) / n).string(); };
	std::vector<io::StampedVehicle> estimate, odometry, true_path;
	for (const auto& s : r.path)
		estimate.push_back({s.device_time_s, s.estimate}),
		    odometry.push_back({s.device_time_s, s.odometry});
	io::writeTum(f("estimate.tum"), estimate);
	io::writeTum(f("odometry.tum"), odometry);
	std::vector<std::string> files{f("estimate.tum"), f("odometry.tum")};
	if (truth && !truth->steps.empty())
	{
		for (const auto& s : truth->steps) true_path.push_back({s.time_s, s.xv_zxphi});
		io::writeTum(f("truth.tum"), true_path);
		files.push_back(f("truth.tum"));
	}
	return files;
}

}  // namespace mrolr::eval
