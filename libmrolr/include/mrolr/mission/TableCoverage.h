#pragma once
/** A search sweep that covers the table (beyond the thesis: its 1.3 and the paper's §4 leave
 * varying tilt and vergence during the search as future work). From the station's estimated pose
 * the plan's table top is seen between two bearings; the views pan from the first to the last
 * bearing less half the cameras' horizontal field of view, `pan_step_deg` apart, the last at the
 * table's far end. Each view fixates the middle of the table top along its bearing (where the ray
 * enters and leaves the top), so tilt and vergence follow the table: steeper and nearer at its
 * near corners, flatter and farther along its middle. Poses in W (x left, y up, z forward,
 * metres); C0 the head centre. */
#include <mrolr/mission/Plan.h>

#include <Eigen/Core>
#include <vector>

namespace mrolr::mission
{
/** One view of the sweep: its bearing in C0 and the point it fixates (C0, m). */
struct TableView
{
	double pan_deg = 0;
	Eigen::Vector3d p_fixinC0_m = Eigen::Vector3d::Zero();
};

/** The plan's table nearest to the base at @p xv_zxphi among those whose centre lies ahead of
 * it; nullptr when none does. */
const PlanTable* tableInFront(const std::vector<PlanTable>& tables, const Eigen::Vector3d& xv_zxphi);

/** The views covering @p table from the base at @p xv_zxphi (C0 @p head_height_m above the floor),
 * right to left (increasing pan); @p half_fov_deg: the cameras' horizontal half field of view.
 * Empty when no corner of the top lies ahead of C0. */
std::vector<TableView> tableViews(const PlanTable& table, const Eigen::Vector3d& xv_zxphi,
                                  double head_height_m, double half_fov_deg, double pan_step_deg);

/** The views half way between consecutive ones of @p views (bearing and fixation point), for the
 * second pass when the first recognised nothing. */
std::vector<TableView> betweenViews(const PlanTable& table, const Eigen::Vector3d& xv_zxphi,
                                    double head_height_m, const std::vector<TableView>& views);

}  // namespace mrolr::mission
