#pragma once
/** Where the base's footprint may go next to the plan's tables: a rectangle (length along the
 * heading, width across, centred on the axle; base::LabmateOptions) tested against every table's
 * footprint grown by kTurnMargin_m, with the motion of a planned leg swept in small increments.
 * The robot uses its own footprint and its own plan (no world): the tables are where the user
 * measured them, the pose is its estimate. W: (z, x) on the floor, φ from z towards x. */
#include <mrolr/base/LabmateModel.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/mission/Plan.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace mrolr::mission
{
/** True when the footprint at @p xv overlaps a table of @p tables grown by @p margin_m. */
bool footprintTouchesTable(const std::vector<PlanTable>& tables, const base::LabmateOptions& base,
                           const Eigen::Vector3d& xv, double margin_m);

/** The first step of @p plan, driven from @p xv, whose swept footprint touches a table (rotations
 * every degree, translations every 2 cm); nothing when the whole plan is clear. */
std::optional<size_t> firstBlockedStep(const std::vector<PlanTable>& tables,
                                       const base::LabmateOptions& base, Eigen::Vector3d xv,
                                       const std::vector<base::PlannedStep>& plan,
                                       double margin_m);

}  // namespace mrolr::mission
