#pragma once
/** A plan made by mrolr-map against the world it was made in: the plan a user would have made of
 * that world (route from [waypoints] and [mission], tables from [table.*], the landmarks to point
 * the head at), and each saved known feature named after a world landmark compared with where it
 * truly is. The true point of a feature on a patch is where the ray from its viewpoint through
 * its estimate meets the patch's plane (the feature is the best corner near the patch centre, not
 * the centre itself); a point landmark's is its position. */
#include <mrolr/mission/MapBuilder.h>
#include <mrolr/world/World.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mrolr::eval
{
/** The plan (no known features) a user gives for @p w: the waypoints before the table waypoint
 * are the route, the table waypoint the station, the home waypoint home; the tables' footprints
 * and heights. Throws world::WorldError naming a missing [mission] waypoint. */
mission::Plan surveyPlanOf(const world::World& w);
/** Where the head is pointed: every landmark flagged `known` (patch centres). */
std::vector<mission::SurveyTarget> surveyTargetsOf(const world::World& w);

struct FeatureCheck
{
	std::string id;
	Eigen::Vector3d p_true = Eigen::Vector3d::Zero(), error_m = Eigen::Vector3d::Zero();
	double mahalanobis_sq = 0;  ///< eᵀ P⁻¹ e with the stored standard deviations
	bool consistent = false;    ///< within the 95 % bound of χ²₃
};
/** Every saved known feature of @p plan named after a landmark of @p w, checked. */
std::vector<FeatureCheck> checkKnownFeatures(const mission::Plan& plan, const world::World& w);
nlohmann::json mapReportJson(const mission::MapBuildResult& r,
                             const std::vector<FeatureCheck>& checks);

}  // namespace mrolr::eval
