// [evaluation]: its keys declared once (util/OptionsBinder.h). Every key is optional: the section
// states only how a user's evaluation set differs from the shipped one.
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::eval
{
namespace
{
using E = EvaluationOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<E>& binder()
{
	static const auto b =
	    util::OptionsBinder<E>()
	        .text("world", &E::world, kOpt)
	        .text("table", &E::table, kOpt)
	        .integer("scenes", &E::scenes, 1, 10000, kOpt)
	        .integer("seed", &E::seed, 0, 1 << 30, kOpt)
	        .integer("min_objects", &E::min_objects, 1, 20, kOpt)
	        .integer("max_objects", &E::max_objects, 1, 20, kOpt)
	        .number("cluster_radius_m", &E::cluster_radius_m, 0.01, 2, kOpt)
	        .number("object_gap_m", &E::object_gap_m, 0, 0.5, kOpt)
	        .number("min_view_distance_m", &E::min_view_distance_m, 0.3, 5, kOpt)
	        .number("max_view_distance_m", &E::max_view_distance_m, 0.3, 5, kOpt)
	        .number("fixation_height_m", &E::fixation_height_m, 0, 1, kOpt)
	        .number("min_visible_fraction", &E::min_visible_fraction, 0, 1, kOpt)
	        .number("visibility_depth_tol_mm", &E::visibility_depth_tol_mm, 0, 100, kOpt)
	        .number("max_rotation_error_deg", &E::max_rotation_error_deg, 0.01, 180, kOpt)
	        .number("max_translation_error_mm", &E::max_translation_error_mm, 0.01, 1e4, kOpt);
	return b;
}
}  // namespace

void EvaluationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& s)
{
	binder().load(cfg, s, *this);
	util::requireInRange(cfg, s, "max_objects", max_objects, min_objects, 20);
	util::requireInRange(cfg, s, "max_view_distance_m", max_view_distance_m, min_view_distance_m,
	                     5);
}

void EvaluationOptions::dump(std::ostream& out) const
{
	binder().dump(out, *this);
}

}  // namespace mrolr::eval
