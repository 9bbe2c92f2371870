// The per-stage option sections of the mission file: [navigation], [search], [retrieval].
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::mission
{
using mrpt::config::CConfigFileBase;

namespace
{
using util::Presence;
constexpr auto kOpt = Presence::Optional;
using N = NavigationOptions;
using Se = SearchOptions;
using R = RetrievalOptions;
using P = PlaceOptions;

// Keys declared optional keep their defaults when absent: the files leave them out
// (docs/config.md); fixed keys are constants of the step, and a file that sets one is refused.
const util::OptionsBinder<N>& navigationBinder()
{
	static const auto b =
	    util::OptionsBinder<N>()
	        .number("measurement_time_s", &N::measurement_time_s, 0, 1e4)
	        .number("waypoint_tolerance_m", &N::waypoint_tolerance_m, 1e-4, 1)
	        .text("landmark_sensor", &N::landmark_sensor, kOpt)
	        .number("image_nssd_ambiguity_margin", &N::image_nssd_ambiguity_margin, -1, 4, kOpt)
	        .number("lost_feature_probability", &N::lost_feature_probability, 0, 1, kOpt)
	        .fixed({"measurements_per_step", "min_mapped_visible", "max_correction_legs",
	                "table_clearance_m", "max_rotation_step_deg", "reverse_max_m"},
	               "mission/MissionOptions.h NavigationOptions");
	return b;
}

const util::OptionsBinder<Se>& searchBinder()
{
	static const auto b = util::OptionsBinder<Se>()
	                          .number("gaze_tilt_deg", &Se::gaze_tilt_deg, -90, 90)
	                          .number("pan_from_deg", &Se::pan_from_deg, -90, 90)
	                          .number("pan_to_deg", &Se::pan_to_deg, -90, 90)
	                          .number("pan_step_deg", &Se::pan_step_deg, 0.1, 90)
	                          .number("head_move_time_s", &Se::head_move_time_s, 0, 1e4)
	                          .text("scene_sensor", &Se::scene_sensor, kOpt)
	                          .flag("render_stereo", &Se::render_stereo, kOpt)
	                          .flag("image_verification", &Se::image_verification, kOpt)
	                          .flag("cover_table", &Se::cover_table, kOpt)
	                          .flag("stop_at_first", &Se::stop_at_first, kOpt)
	                          .flag("behind_found", &Se::behind_found, kOpt)
	                          .flag("rival_models", &Se::rival_models, kOpt);
	return b;
}

const util::OptionsBinder<R>& retrievalBinder()
{
	static const auto b =
	    util::OptionsBinder<R>()
	        .number("approach_mm", &R::approach_mm, 0, 1e4)
	        .number("lift_mm", &R::lift_mm, 0, 1e4)
	        .number("arm_move_time_s", &R::arm_move_time_s, 0, 1e4)
	        .flag("visual_verification", &R::visual_verification, kOpt)
	        .number("max_grasp_correction_mm", &R::max_grasp_correction_mm, 0, 1000, kOpt)
	        .number("inject_pose_error_mm", &R::inject_pose_error_mm, -500, 500, kOpt)
	        .number("min_held_width_mm", &R::min_held_width_mm, 0, 1000, kOpt)
	        .fixed({"grasp_yaw_search_deg"}, "mission/MissionOptions.h RetrievalOptions");
	return b;
}

const util::OptionsBinder<P>& placeBinder()
{
	static const auto b = util::OptionsBinder<P>()
	                          .flag("enabled", &P::enabled, kOpt)
	                          .number("drop_mm", &P::drop_mm, 0, 100, kOpt)
	                          .number("margin_mm", &P::margin_mm, 0, 200, kOpt)
	                          .number("self_margin_mm", &P::self_margin_mm, 0, 100, kOpt)
	                          .number("grid_step_mm", &P::grid_step_mm, 5, 500, kOpt)
	                          .number("yaw_step_deg", &P::yaw_step_deg, 1, 360, kOpt)
	                          .number("check_step_mm", &P::check_step_mm, 1, 100, kOpt);
	return b;
}
}  // namespace

void NavigationOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	navigationBinder().load(c, s, *this);
	if (landmark_sensor.empty())
		throw util::ConfigError(util::describeKey(c, s, "landmark_sensor") +
		                        ": empty (images, or a simulated sensor such as ideal_sim)");
	landmark_source =
	    landmark_sensor == "images" ? LandmarkSource::Images : LandmarkSource::Simulated;
}

void SearchOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	searchBinder().load(c, s, *this);
	if (scene_sensor.empty())
		throw util::ConfigError(util::describeKey(c, s, "scene_sensor") +
		                        ": empty (reconstructed, or a simulated sensor such as exact_sim)");
	scene_source =
	    scene_sensor == "reconstructed" ? SceneSource::Reconstructed : SceneSource::Simulated;
	util::requireInRange(c, s, "pan_to_deg", pan_to_deg, pan_from_deg, 90);
}

void RetrievalOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	retrievalBinder().load(c, s, *this);
}

void PlaceOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	placeBinder().load(c, s, *this);
}

void NavigationOptions::dump(std::ostream& out) const
{
	navigationBinder().dump(out, *this);
}

void SearchOptions::dump(std::ostream& out) const
{
	searchBinder().dump(out, *this);
}

void RetrievalOptions::dump(std::ostream& out) const
{
	retrievalBinder().dump(out, *this);
}

void PlaceOptions::dump(std::ostream& out) const
{
	placeBinder().dump(out, *this);
}

}  // namespace mrolr::mission
