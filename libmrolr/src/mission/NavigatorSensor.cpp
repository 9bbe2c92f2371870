// Navigation measurements from a simulated landmark sensor (landmark_sensor = ideal_sim, tests):
// the thesis's cycle (5.7) on named landmarks, associated by name.
#include <mrolr/mission/Navigator.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>

#include <algorithm>
#include <cmath>

namespace mrolr::mission
{
namespace
{
const hw::LandmarkSensor::Sighting* find(const std::vector<hw::LandmarkSensor::Sighting>& seen,
                                         const std::string& name)
{
	for (const auto& s : seen)
		if (s.name == name) return &s;
	return nullptr;
}
}  // namespace

std::vector<size_t> Navigator::visibleMapped(const std::vector<hw::LandmarkSensor::Sighting>& seen)
{
	std::vector<size_t> out;
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
	{
		const bool predicted = slam::assessVisibility(filter_.vehicle(), filter_.feature(i),
		                                              filter_.info(i).p_C0atInitInW,
		                                              o_.slam) == slam::Visibility::Visible;
		if (predicted && find(seen, filter_.info(i).label)) out.push_back(i);
	}
	return out;
}

void Navigator::initialiseNewFeature(const std::vector<hw::LandmarkSensor::Sighting>& seen)
{
	const hw::LandmarkSensor::Sighting* best = nullptr;
	for (const auto& s : seen)
	{
		bool mapped = false;
		for (size_t i = 0; i < filter_.numFeatures() && !mapped; ++i)
			mapped = filter_.info(i).label == s.name;
		if (!mapped && (!best || std::abs(s.h[0]) < std::abs(best->h[0]))) best = &s;
	}
	if (!best) return;
	ComputeTimer t(timeline_);
	filter_.initialiseFeature(best->name, best->h);
}

void Navigator::measureWithSensor()
{
	const auto seen = sensor_->visible();
	auto visible = visibleMapped(seen);
	if (static_cast<int>(visible.size()) < o_.navigation.min_mapped_visible)
		initialiseNewFeature(seen);
	std::vector<slam::Observation> obs;
	for (int k = 0; k < o_.navigation.measurements_per_step && !visible.empty(); ++k)
	{
		std::optional<size_t> pick;
		{
			ComputeTimer t(timeline_);
			pick =
			    slam::largestVolume(filter_.stateVector(), filter_.covariance(), visible, o_.slam);
		}
		if (!pick) break;
		const size_t i = visible[*pick];
		visible.erase(visible.begin() + static_cast<long>(*pick));
		timeline_.advance(o_.navigation.measurement_time_s);
		if (lostThisTime(i)) continue;
		if (const auto h = sensor_->measure(filter_.info(i).label)) obs.push_back({i, *h});
	}
	ComputeTimer t(timeline_);
	if (!obs.empty())
	{
		const auto report = filter_.update(obs);
		measurements += static_cast<int>(report.accepted.size());
		rejected += static_cast<int>(report.rejected.size());
		for (size_t j = 0; j < report.accepted.size(); ++j)
		{
			filter_.recordAttempt(report.accepted[j], true);
			noteNis(filter_.info(report.accepted[j]).label, report.nis[j], true);
		}
		for (size_t j = 0; j < report.rejected.size(); ++j)
		{
			filter_.recordAttempt(report.rejected[j], false);
			noteNis(filter_.info(report.rejected[j]).label, report.rejected_nis[j], false);
		}
	}
	deleteFailingFeatures();
}

bool Navigator::lostThisTime(size_t i)
{
	const double p = o_.navigation.lost_feature_probability;
	if (p <= 0 || std::uniform_real_distribution<double>(0, 1)(rng_) >= p) return false;
	filter_.recordAttempt(i, false);
	++lost;
	return true;
}

void Navigator::deleteFailingFeatures()
{
	for (size_t i = filter_.numFeatures(); i-- > 0;)
		if (!filter_.info(i).known && filter_.shouldDelete(i))
		{
			filter_.deleteFeature(i);
			++deleted_features;
		}
}

}  // namespace mrolr::mission
