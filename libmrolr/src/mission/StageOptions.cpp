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
	max_range_m = readDouble(c, s, "max_range_m");
	true_std_pan_rad = readDouble(c, s, "true_std_pan_rad");
	true_std_elevation_rad = readDouble(c, s, "true_std_elevation_rad");
	true_std_vergence_rad = readDouble(c, s, "true_std_vergence_rad");
	measurement_time_s = readDouble(c, s, "measurement_time_s");
	waypoint_tolerance_m = readDouble(c, s, "waypoint_tolerance_m");
	max_correction_legs = static_cast<int>(util::readInt(c, s, "max_correction_legs"));
	table_clearance_m = readDouble(c, s, "table_clearance_m");
	max_rotation_step_deg = readDouble(c, s, "max_rotation_step_deg", max_rotation_step_deg);
	reverse_max_m = readDouble(c, s, "reverse_max_m", reverse_max_m);
	if (util::hasKey(c, s, "measurement_source"))
		measurement_source = util::readString(c, s, "measurement_source");
	if (measurement_source != "ideal" && measurement_source != "images")
		throw util::ConfigError(util::describeKey(c, s, "measurement_source") + ": '" +
		                        measurement_source + "' is not one of ideal, images");
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
	    << "\nmin_mapped_visible = " << min_mapped_visible << "\nmax_range_m = " << max_range_m
	    << "\ntrue_std_pan_rad = " << true_std_pan_rad
	    << "\ntrue_std_elevation_rad = " << true_std_elevation_rad
	    << "\ntrue_std_vergence_rad = " << true_std_vergence_rad
	    << "\nmeasurement_time_s = " << measurement_time_s
	    << "\nwaypoint_tolerance_m = " << waypoint_tolerance_m
	    << "\nmax_correction_legs = " << max_correction_legs
	    << "\ntable_clearance_m = " << table_clearance_m
	    << "\nmax_rotation_step_deg = " << max_rotation_step_deg
	    << "\nreverse_max_m = " << reverse_max_m << "\nmeasurement_source = " << measurement_source
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
	endpoint_sigma_mm = readDouble(c, s, "endpoint_sigma_mm");
	missing_fraction = readDouble(c, s, "missing_fraction");
	fragment_probability = readDouble(c, s, "fragment_probability");
	hide_back_side = util::readBool(c, s, "hide_back_side", hide_back_side);
	max_object_range_m = readDouble(c, s, "max_object_range_m");
	render_stereo = util::readBool(c, s, "render_stereo", render_stereo);
	if (util::hasKey(c, s, "scene_source")) scene_source = util::readString(c, s, "scene_source");
	image_verification = util::readBool(c, s, "image_verification", image_verification);
	if (scene_source != "simulated" && scene_source != "reconstructed")
		throw util::ConfigError(util::describeKey(c, s, "scene_source") + ": '" + scene_source +
		                        "' is not one of simulated, reconstructed");
	util::requireInRange(c, s, "pan_step_deg", pan_step_deg, 0.1, 90);
	util::requireInRange(c, s, "pan_to_deg", pan_to_deg, pan_from_deg, 90);
	util::requireInRange(c, s, "missing_fraction", missing_fraction, 0, 0.9);
}

void SearchOptions::dump(std::ostream& out) const
{
	out << "gaze_tilt_deg = " << gaze_tilt_deg << "\npan_from_deg = " << pan_from_deg
	    << "\npan_to_deg = " << pan_to_deg << "\npan_step_deg = " << pan_step_deg
	    << "\nhead_move_time_s = " << head_move_time_s
	    << "\nendpoint_sigma_mm = " << endpoint_sigma_mm
	    << "\nmissing_fraction = " << missing_fraction
	    << "\nfragment_probability = " << fragment_probability
	    << "\nhide_back_side = " << (hide_back_side ? "true" : "false")
	    << "\nmax_object_range_m = " << max_object_range_m
	    << "\nrender_stereo = " << (render_stereo ? "true" : "false")
	    << "\nscene_source = " << scene_source
	    << "\nimage_verification = " << (image_verification ? "true" : "false") << "\n";
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
}

void RetrievalOptions::dump(std::ostream& out) const
{
	out << "approach_mm = " << approach_mm << "\nlift_mm = " << lift_mm
	    << "\narm_move_time_s = " << arm_move_time_s
	    << "\nvisual_verification = " << (visual_verification ? "true" : "false")
	    << "\ngrasp_yaw_search_deg = " << grasp_yaw_search_deg
	    << "\nmax_grasp_correction_mm = " << max_grasp_correction_mm
	    << "\ninject_pose_error_mm = " << inject_pose_error_mm << "\n";
}

}  // namespace mrolr::mission
