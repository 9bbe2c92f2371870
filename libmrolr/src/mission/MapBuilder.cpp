// Known features from a drive (thesis 5.6.2): survey at the start, drive the route, save.
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/MapBuilder.h>
#include <mrolr/mission/MissionStereoHead.h>

#include <cmath>

namespace mrolr::mission
{
namespace
{
bool wellMapped(const SavedFeature& f)
{
	const double sigma = std::sqrt(f.landmark.P.diagonal().maxCoeff());
	return sigma <= MapBuilder::kMaxSavedSigma_m && f.successes >= MapBuilder::kMinSavedMatches;
}

PlanFeature planFeature(const SavedFeature& f)
{
	PlanFeature k;
	k.id = f.landmark.label;
	k.p_FinW = f.landmark.p_FinW;
	k.sigma_m = f.landmark.P.diagonal().cwiseSqrt();
	k.patch = f.patch;
	k.patch_file = "patches/" + k.id + ".png";
	k.p_viewinW = f.p_viewinW;
	return k;
}
}  // namespace

MapBuilder::MapBuilder(const MissionOptions& o, RobotDevices devices) : o_(o), dev_(devices)
{
	o_.plan.known_features.clear();  // the map is made, not given
	o_.navigation.landmark_source = LandmarkSource::Images;
	if (!dev_.base || !dev_.head || !dev_.arm)
		throw std::invalid_argument("MapBuilder: every device (base, head, arm) must be given");
}

MapBuildResult MapBuilder::build(const std::vector<SurveyTarget>& targets)
{
	MapBuildResult r;
	r.plan = o_.plan;
	r.plan.known_features.clear();
	MissionStereoHead head(*dev_.head);
	Navigator nav(o_, *dev_.base, r.timeline);
	nav.useImages(head, [&head] { return head.grabSeconds(); });
	nav.stop_requested = [this] { return stop_flag && stop_flag->load(); };
	nav.on_step = [&](const PathSample& s)
	{
		if (on_progress) on_progress(r.timeline.stage(), s);
	};
	std::unique_ptr<ObstacleAvoidance> obstacles;
	if (o_.obstacle_mode)
	{
		auto look = [this](const geometry::HeadAngles& a)
		{
			dev_.head->moveTo(a);
			return dev_.head->grab();
		};
		obstacles = std::make_unique<ObstacleAvoidance>(geometry::BiSightHead(o_.bisight),
		                                                o_.obstacle, look, r.timeline);
		attachObstacleAvoidance(nav, *obstacles, o_);
	}
	try
	{
		r.timeline.beginStage("survey");
		for (const auto& t : targets)
		{
			std::string why;
			if (nav.acquireNamed(t.id, t.p_aim_inW, why))
				r.locked.push_back(t.id);
			else
				r.not_locked.push_back(t.id + " (" + why + ")");
			r.timeline.note(t.id + (why.empty() ? ": locked on" : ": not locked on: " + why));
		}
		r.timeline.beginStage("drive");
		for (size_t i = 1; i < o_.plan.route.size(); ++i) nav.driveTo(o_.plan.route[i]);
		for (const auto& s : o_.plan.stations) nav.driveTo(s);
		nav.driveTo(o_.plan.home);
		r.timeline.endStage();
	}
	catch (const std::exception& e)  // a device, the bumper or a stop request: keep what was mapped
	{
		r.stopped = true;
		r.failure = std::string("stopped: ") + e.what();
		r.timeline.note(r.failure);
		try
		{
			dev_.base->step({0, 0, 0});
		}
		catch (const std::exception&)
		{
		}
	}
	r.all = nav.savedFeatures();
	for (const auto& f : r.all)
		if (wellMapped(f)) r.plan.known_features.push_back(planFeature(f));
	r.path = nav.path();
	r.nis = nav.nis();
	return r;
}

}  // namespace mrolr::mission
