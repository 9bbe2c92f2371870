#pragma once
/** Docking poses from which the arm can reach a recognised object (thesis 6.7, 8.2: the transport
 * robot came to the object; beyond the thesis's fixed arm). The arm stands on the base at
 * T_C0inA, so where the base stops decides what the arm reaches. For the plan's table under the
 * object, the candidates face each of its four sides from `standoff_m` (the base's centre from the
 * side), placed along the side so that the object lies straight ahead of the arm's column, and
 * `lateral_steps` steps of `lateral_step_m` either way of that, as long as the base's centre stays
 * in front of the side. A candidate nearer than standoff_m to any of the plan's tables is dropped. They come by side, the side with the shortest path from where
 * the robot stands (round the plan's tables, as the navigation drives) first, and on a side the
 * candidates nearest the object's line first (the most margin for the arm); the mission takes
 * the first whose grasp is feasible (Retrieval::feasibleAt). W: x left, y up, z forward, metres;
 * φ from z towards x.
 */
#include <mrolr/mission/Plan.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** Section [docking] of the mission file; every key optional. */
struct DockingOptions
{
	/** When the grasp is not feasible from where the object was found, drive to a docking pose
	 * from which it is (false: report the grasp infeasible). */
	bool drive_to_reach = true;
	double standoff_m = 0.55;      ///< base centre to the table's side it faces
	double lateral_step_m = 0.10;  ///< spacing of the candidates along a side
	int lateral_steps = 3;         ///< candidates either way of the object's line
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One candidate docking pose. */
struct DockCandidate
{
	NamedPose pose;        ///< base pose (z, x, φ) in W, facing the table
	std::string side;      ///< e.g. "table.main -z side" (the table's own axes)
	double travel_m = 0;   ///< path length from the start, round the plan's tables
	double lateral_m = 0;  ///< offset along the side from the object's line
};

/** What the docking did before the grasp (report.json `retrieval.docking`). */
struct DockingResult
{
	bool needed = false;   ///< the grasp was not feasible from where the object was found
	bool planned = false;  ///< a candidate with a feasible grasp was found
	bool reached = false;  ///< the base drove there and recognised the object again
	std::vector<std::string> reasons_before;  ///< why the grasp was not feasible before
	std::vector<std::string> reasons_nearest;  ///< why not from the first candidate, if not
	DockCandidate chosen;
	int candidates = 0, candidates_checked = 0;
	int candidates_near_walls = 0;  ///< left out: the base could not turn there (the plan's [room])
	std::string reason;  ///< why there was no docking pose, or what failed on the way
	double compute_s = 0;  ///< planning (robot compute, wall s)
	/** The recognition at the docking pose (C0 there, mm): the grasp is planned on it. */
	bool recognised = false;
	bool ambiguous = false;  ///< that recognition was ambiguous too
	/** Not recognised in the docking view: the table was swept again from the docking pose (the
	 * search's sighting may have been a false match), and whether that sweep found the target. */
	bool swept_again = false, found_again = false;
	/** What that sweep found was out of reach from here: the base docked once more for it. */
	bool docked_again = false;
	std::optional<uint64_t> frame;  ///< its stereo pair
};

/** The plan's table whose top is nearest to @p p_OinW_m (horizontally); nullptr without tables. */
const PlanTable* tableUnder(const std::vector<PlanTable>& tables, const Eigen::Vector3d& p_OinW_m);

/** The candidates for an object at @p p_OinW_m on @p table, in the order above, travel from
 * @p from_zxphi. @p T_C0inA_mm: the arm's mount; @p head_height_m: C0 above the floor;
 * @p clearance_m: what the navigation keeps from tables when it goes round them. */
std::vector<DockCandidate> dockCandidates(const std::vector<PlanTable>& tables,
                                          const PlanTable& table, const Eigen::Vector3d& p_OinW_m,
                                          const Eigen::Vector3d& from_zxphi,
                                          const Eigen::Isometry3d& T_C0inA_mm,
                                          double head_height_m, double clearance_m,
                                          const DockingOptions& o);

}  // namespace mrolr::mission
