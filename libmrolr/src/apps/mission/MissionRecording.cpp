// The world side's truth in the recording, and a replay's report checked against the original.
#include <mrolr/apps/MissionRecording.h>
#include <mrolr/geometry/Frames.h>

#include <mrpt/obs/CObservationRobotPose.h>

#include <set>

namespace mrolr::apps
{
std::function<void(io::ObservationLogWriter&)> truthRecorder(const sim::Lab& lab)
{
	return [&lab](io::ObservationLogWriter& log)
	{
		if (lab.truth().steps.empty()) return;
		const auto& s = lab.truth().steps.back();
		auto gt = mrpt::obs::CObservationRobotPose::Create();
		gt->sensorLabel = "GROUND_TRUTH";
		gt->timestamp = mrpt::Clock::fromDouble(1.7e9 + s.time_s);
		gt->pose.mean = mrpt::poses::CPose3D(geometry::vehicleToMrpt(s.xv_zxphi));
		log.write(*gt);
	};
}

std::vector<sim::TruthLog::Step> recordedTruthSteps(const std::string& rawlog_path)
{
	std::vector<sim::TruthLog::Step> steps;
	for (const auto& obs : io::readObservationLog(rawlog_path).observations)
		if (obs->sensorLabel == "GROUND_TRUTH")
			if (const auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obs))
				steps.push_back({mrpt::Clock::toDouble(gt->timestamp) - 1.7e9,
				                 geometry::vehicleFromMrpt(mrpt::poses::CPose2D(gt->pose.mean))});
	return steps;
}

namespace
{
/** Keys whose values are wall-clock times or belong to the run, not to what the robot decided. */
bool ignored(const std::string& key)
{
	static const std::set<std::string> keys = {"render_seconds", "serial_links", "replay", "plan",
	                                           "replay_divergence", "eval", "ms", "timeline"};
	return keys.count(key) || key.find("compute") != std::string::npos;
}

void compare(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
             std::vector<std::string>& out)
{
	if (b.is_null()) return;  // eval's field, not the robot's
	if (a.is_object() && b.is_object())
	{
		for (const auto& [k, v] : b.items())
			if (!ignored(k)) compare(a.contains(k) ? a[k] : nlohmann::json(), v, path.empty() ? k : path + "." + k, out);
		return;
	}
	if (a.is_array() && b.is_array() && a.size() == b.size())
	{
		for (size_t i = 0; i < a.size(); ++i)
			compare(a[i], b[i], path + "[" + std::to_string(i) + "]", out);
		return;
	}
	if (a != b) out.push_back(path);
}
}  // namespace

std::vector<std::string> reportDifferences(const nlohmann::json& original,
                                           const nlohmann::json& replay, size_t max_listed)
{
	std::vector<std::string> all;
	compare(original, replay, "", all);
	if (all.size() <= max_listed) return all;
	std::vector<std::string> out(all.begin(), all.begin() + max_listed);
	out.push_back("… " + std::to_string(all.size()) + " differences in all");
	return out;
}

}  // namespace mrolr::apps
