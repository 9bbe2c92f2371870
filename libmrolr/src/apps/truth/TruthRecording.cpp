// The world side's truth as GROUND_TRUTH records.
#include <mrolr/apps/TruthRecording.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>

#include <mrpt/obs/CObservationRobotPose.h>

namespace mrolr::apps
{
namespace
{
mrpt::obs::CObservationRobotPose::Ptr truthOf(const sim::TruthLog::Step& s)
{
	auto gt = mrpt::obs::CObservationRobotPose::Create();
	gt->sensorLabel = "GROUND_TRUTH";
	gt->timestamp = io::stampOf(s.time_s);
	gt->pose.mean = mrpt::poses::CPose3D(geometry::vehicleToMrpt(s.xv_zxphi));
	return gt;
}
}  // namespace

std::function<mrpt::obs::CObservation::Ptr()> truthRecorder(const sim::Lab& lab)
{
	return [&lab]() -> mrpt::obs::CObservation::Ptr
	{
		if (lab.truth().steps.empty()) return nullptr;
		return truthOf(lab.truth().steps.back());
	};
}

std::vector<sim::TruthLog::Step> recordedTruthSteps(const std::string& rawlog_path)
{
	std::vector<sim::TruthLog::Step> steps;
	for (const auto& obs : io::readObservationLog(rawlog_path).observations)
		if (obs->sensorLabel == "GROUND_TRUTH")
			if (const auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obs))
				steps.push_back({io::timeOf(gt->timestamp),
				                 geometry::vehicleFromMrpt(mrpt::poses::CPose2D(gt->pose.mean))});
	return steps;
}

void writeTruthRawlog(const sim::Lab& lab, const std::string& path)
{
	io::ObservationLogWriter log(path);
	for (const auto& s : lab.truth().steps) log.write(*truthOf(s));
}

}  // namespace mrolr::apps
