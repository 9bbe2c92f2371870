#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::eval
{
namespace
{
double readIn(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& k,
              double fallback, double lo, double hi)
{
	const double v = util::readDouble(cfg, s, k, fallback);
	util::requireInRange(cfg, s, k, v, lo, hi);
	return v;
}

int readCount(const mrpt::config::CConfigFileBase& cfg, const std::string& s, const std::string& k,
              int fallback, int lo, int hi)
{
	const long v = util::readInt(cfg, s, k, fallback);
	util::requireInRange(cfg, s, k, static_cast<double>(v), lo, hi);
	return static_cast<int>(v);
}
}  // namespace

void EvaluationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& s)
{
	if (util::hasKey(cfg, s, "world")) world = util::readString(cfg, s, "world");
	if (util::hasKey(cfg, s, "table")) table = util::readString(cfg, s, "table");
	scenes = readCount(cfg, s, "scenes", scenes, 1, 10000);
	seed = static_cast<unsigned>(readCount(cfg, s, "seed", static_cast<int>(seed), 0, 1 << 30));
	min_objects = readCount(cfg, s, "min_objects", min_objects, 1, 20);
	max_objects = readCount(cfg, s, "max_objects", max_objects, min_objects, 20);
	cluster_radius_m = readIn(cfg, s, "cluster_radius_m", cluster_radius_m, 0.01, 2);
	object_gap_m = readIn(cfg, s, "object_gap_m", object_gap_m, 0, 0.5);
	min_view_distance_m = readIn(cfg, s, "min_view_distance_m", min_view_distance_m, 0.3, 5);
	max_view_distance_m =
	    readIn(cfg, s, "max_view_distance_m", max_view_distance_m, min_view_distance_m, 5);
	fixation_height_m = readIn(cfg, s, "fixation_height_m", fixation_height_m, 0, 1);
	min_visible_fraction = readIn(cfg, s, "min_visible_fraction", min_visible_fraction, 0, 1);
	visibility_depth_tol_mm =
	    readIn(cfg, s, "visibility_depth_tol_mm", visibility_depth_tol_mm, 0, 100);
	max_rotation_error_deg =
	    readIn(cfg, s, "max_rotation_error_deg", max_rotation_error_deg, 0.01, 180);
	max_translation_error_mm =
	    readIn(cfg, s, "max_translation_error_mm", max_translation_error_mm, 0.01, 1e4);
}

void EvaluationOptions::dump(std::ostream& out) const
{
	out << "world = " << world << "\ntable = " << table << "\nscenes = " << scenes
	    << "\nseed = " << seed << "\nmin_objects = " << min_objects
	    << "\nmax_objects = " << max_objects << "\ncluster_radius_m = " << cluster_radius_m
	    << "\nobject_gap_m = " << object_gap_m << "\nmin_view_distance_m = " << min_view_distance_m
	    << "\nmax_view_distance_m = " << max_view_distance_m
	    << "\nfixation_height_m = " << fixation_height_m
	    << "\nmin_visible_fraction = " << min_visible_fraction
	    << "\nvisibility_depth_tol_mm = " << visibility_depth_tol_mm
	    << "\nmax_rotation_error_deg = " << max_rotation_error_deg
	    << "\nmax_translation_error_mm = " << max_translation_error_mm << "\n";
}

}  // namespace mrolr::eval
