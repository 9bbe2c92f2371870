// The per-stage option sections of the mission file: [navigation], [search], [retrieval].
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::mission
{
using mrpt::config::CConfigFileBase;
using util::readDouble;

void NavigationOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	measurements_per_step = static_cast<int>(util::readInt(c, s, "measurements_per_step"));
	min_mapped_visible = static_cast<int>(util::readInt(c, s, "min_mapped_visible"));
	measurement_time_s = readDouble(c, s, "measurement_time_s");
	waypoint_tolerance_m = readDouble(c, s, "waypoint_tolerance_m");
	max_correction_legs = static_cast<int>(util::readInt(c, s, "max_correction_legs"));
	table_clearance_m = readDouble(c, s, "table_clearance_m");
	max_rotation_step_deg = readDouble(c, s, "max_rotation_step_deg", max_rotation_step_deg);
	reverse_max_m = readDouble(c, s, "reverse_max_m", reverse_max_m);
	if (util::hasKey(c, s, "landmark_sensor"))
		landmark_sensor = util::readString(c, s, "landmark_sensor");
	if (landmark_sensor.empty())
		throw util::ConfigError(util::describeKey(c, s, "landmark_sensor") +
		                        ": empty (images, or a simulated sensor such as ideal_sim)");
	landmark_source =
	    landmark_sensor == "images" ? LandmarkSource::Images : LandmarkSource::Simulated;
	image_nssd_ambiguity_margin =
	    readDouble(c, s, "image_nssd_ambiguity_margin", image_nssd_ambiguity_margin);
	util::requireInRange(c, s, "image_nssd_ambiguity_margin", image_nssd_ambiguity_margin, -1, 4);
	lost_feature_probability =
	    readDouble(c, s, "lost_feature_probability", lost_feature_probability);
	util::requireInRange(c, s, "lost_feature_probability", lost_feature_probability, 0, 1);
	util::requireInRange(c, s, "max_rotation_step_deg", max_rotation_step_deg, 0, 360);
	util::requireInRange(c, s, "reverse_max_m", reverse_max_m, 0, 10);
	util::requireInRange(c, s, "measurements_per_step", measurements_per_step, 0, 20);
	util::requireInRange(c, s, "max_correction_legs", max_correction_legs, 0, 10);
	util::requireInRange(c, s, "waypoint_tolerance_m", waypoint_tolerance_m, 1e-4, 1);
}

void NavigationOptions::dump(std::ostream& out) const
{
	out << "measurements_per_step = " << measurements_per_step
	    << "\nmin_mapped_visible = " << min_mapped_visible
	    << "\nmeasurement_time_s = " << measurement_time_s
	    << "\nwaypoint_tolerance_m = " << waypoint_tolerance_m
	    << "\nmax_correction_legs = " << max_correction_legs
	    << "\ntable_clearance_m = " << table_clearance_m
	    << "\nmax_rotation_step_deg = " << max_rotation_step_deg
	    << "\nreverse_max_m = " << reverse_max_m << "\nlandmark_sensor = " << landmark_sensor
	    << "\nimage_nssd_ambiguity_margin = " << image_nssd_ambiguity_margin
	    << "\nlost_feature_probability = " << lost_feature_probability << "\n";
}

void SearchOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	gaze_tilt_deg = readDouble(c, s, "gaze_tilt_deg");
	pan_from_deg = readDouble(c, s, "pan_from_deg");
	pan_to_deg = readDouble(c, s, "pan_to_deg");
	pan_step_deg = readDouble(c, s, "pan_step_deg");
	head_move_time_s = readDouble(c, s, "head_move_time_s");
	render_stereo = util::readBool(c, s, "render_stereo", render_stereo);
	if (util::hasKey(c, s, "scene_sensor")) scene_sensor = util::readString(c, s, "scene_sensor");
	if (scene_sensor.empty())
		throw util::ConfigError(util::describeKey(c, s, "scene_sensor") +
		                        ": empty (reconstructed, or a simulated sensor such as exact_sim)");
	scene_source =
	    scene_sensor == "reconstructed" ? SceneSource::Reconstructed : SceneSource::Simulated;
	image_verification = util::readBool(c, s, "image_verification", image_verification);
	cover_table = util::readBool(c, s, "cover_table", cover_table);
	stop_at_first = util::readBool(c, s, "stop_at_first", stop_at_first);
	behind_found = util::readBool(c, s, "behind_found", behind_found);
	util::requireInRange(c, s, "pan_step_deg", pan_step_deg, 0.1, 90);
	util::requireInRange(c, s, "pan_to_deg", pan_to_deg, pan_from_deg, 90);
}

void SearchOptions::dump(std::ostream& out) const
{
	out << "gaze_tilt_deg = " << gaze_tilt_deg << "\npan_from_deg = " << pan_from_deg
	    << "\npan_to_deg = " << pan_to_deg << "\npan_step_deg = " << pan_step_deg
	    << "\nhead_move_time_s = " << head_move_time_s << "\nscene_sensor = " << scene_sensor
	    << "\nrender_stereo = " << (render_stereo ? "true" : "false")
	    << "\nimage_verification = " << (image_verification ? "true" : "false")
	    << "\ncover_table = " << (cover_table ? "true" : "false")
	    << "\nstop_at_first = " << (stop_at_first ? "true" : "false")
	    << "\nbehind_found = " << (behind_found ? "true" : "false") << "\n";
}

void RetrievalOptions::loadFromConfigFile(const CConfigFileBase& c, const std::string& s)
{
	approach_mm = readDouble(c, s, "approach_mm");
	lift_mm = readDouble(c, s, "lift_mm");
	arm_move_time_s = readDouble(c, s, "arm_move_time_s");
	visual_verification = util::readBool(c, s, "visual_verification", visual_verification);
	grasp_yaw_search_deg = readDouble(c, s, "grasp_yaw_search_deg");
	util::requireInRange(c, s, "grasp_yaw_search_deg", grasp_yaw_search_deg, 0, 180);
	max_grasp_correction_mm = readDouble(c, s, "max_grasp_correction_mm", max_grasp_correction_mm);
	util::requireInRange(c, s, "max_grasp_correction_mm", max_grasp_correction_mm, 0, 1000);
	inject_pose_error_mm = readDouble(c, s, "inject_pose_error_mm", inject_pose_error_mm);
	util::requireInRange(c, s, "inject_pose_error_mm", inject_pose_error_mm, -500, 500);
	min_held_width_mm = readDouble(c, s, "min_held_width_mm", min_held_width_mm);
	util::requireInRange(c, s, "min_held_width_mm", min_held_width_mm, 0, 1000);
}

void RetrievalOptions::dump(std::ostream& out) const
{
	out << "approach_mm = " << approach_mm << "\nlift_mm = " << lift_mm
	    << "\narm_move_time_s = " << arm_move_time_s
	    << "\nvisual_verification = " << (visual_verification ? "true" : "false")
	    << "\ngrasp_yaw_search_deg = " << grasp_yaw_search_deg
	    << "\nmax_grasp_correction_mm = " << max_grasp_correction_mm
	    << "\ninject_pose_error_mm = " << inject_pose_error_mm
	    << "\nmin_held_width_mm = " << min_held_width_mm << "\n";
}

void PlaceOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	enabled = util::readBool(c, s, "enabled", enabled);
	auto num = [&](const char* key, double& v, double lo, double hi)
	{
		v = util::readDouble(c, s, key, v);
		util::requireInRange(c, s, key, v, lo, hi);
	};
	num("drop_mm", drop_mm, 0, 100);
	num("margin_mm", margin_mm, 0, 200);
	num("self_margin_mm", self_margin_mm, 0, 100);
	num("grid_step_mm", grid_step_mm, 5, 500);
	num("yaw_step_deg", yaw_step_deg, 1, 360);
	num("check_step_mm", check_step_mm, 1, 100);
}

void PlaceOptions::dump(std::ostream& out) const
{
	out << "enabled = " << (enabled ? "true" : "false") << "\ndrop_mm = " << drop_mm
	    << "\nmargin_mm = " << margin_mm << "\nself_margin_mm = " << self_margin_mm
	    << "\ngrid_step_mm = " << grid_step_mm << "\nyaw_step_deg = " << yaw_step_deg
	    << "\ncheck_step_mm = " << check_step_mm << "\n";
}

}  // namespace mrolr::mission
