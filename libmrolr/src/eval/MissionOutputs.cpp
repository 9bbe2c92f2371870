// The whole set of a run's outputs but its recording (mission/DeviceRecorder.h writes that).
#include <mrolr/eval/MissionEval.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/geometry/Frames.h>
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
	return out;
}

}  // namespace mrolr::eval
