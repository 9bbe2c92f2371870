#pragma once
/** Retrieval of a recognised object with the docked RTX arm (thesis 6.6–6.7, 7.2.2):
 *   T_OinA = T_C0inA · T_OinC0 (eq 6.7.1, T_C0inA known from the docking),
 *   T_GinA = T_OinA · T_GinO (the model's grasp line),
 * the grasp is checked (reach, opening, table, arm/GraspFeasibility.h, and a reachable pre-grasp
 * pose) before the arm moves; the arm goes to a pre-grasp pose approach_mm back along z_G (or above
 * the grasp when that is out of reach), re-observes the object with the head and
 * corrects the grasp (visual verification, beyond the thesis's open loop), closes the gripper and
 * lifts. An unreachable or infeasible grasp is reported with its reasons and the arm never moves.
 */
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/ObjectSearch.h>

#include <functional>

namespace mrolr::mission
{
struct RetrievalResult
{
	bool attempted = false;  ///< the arm moved
	bool feasible = false;
	std::vector<std::string> reasons;                          ///< why not feasible / what failed
	Eigen::Isometry3d T_OinA = Eigen::Isometry3d::Identity();  ///< mm, from the first recognition
	Eigen::Isometry3d T_GinA = Eigen::Isometry3d::Identity();  ///< grasp actually used, mm
	double grasp_turn_deg = 0;  ///< turn of the model's grasp about O's vertical axis
	arm::RtxJoints joints;      ///< joint solution of the grasp
	bool verified = false;      ///< the re-observation recognised the object
	double correction_mm = 0;   ///< |t(T_GinA corrected) − t(T_GinA first)|
	double correction_deg = 0;
	bool retrieved = false;  ///< the gripper holds the target
	std::string grasped;     ///< the instance in the gripper
};

class Retrieval
{
 public:
	/** @p reobserve: a new recognition of the object from the head (returns T_OinC0 in mm, or
	 * nothing when not recognised); @p grasped: the instance the gripper holds ("" if none). */
	Retrieval(const MissionOptions& o, const model::WireFrame& target);
	RetrievalResult run(const Eigen::Isometry3d& T_OinC0_mm, double table_top_height_m,
	                    hw::ArmDevice& arm,
	                    const std::function<std::optional<Eigen::Isometry3d>()>& reobserve,
	                    const std::function<std::string()>& grasped, Timeline& timeline) const;
	/** The table plane's height in A (mm) for a table top @p top_height_m above the floor. */
	double tableZinA(double top_height_m) const;

 private:
	arm::GraspCheck check(const Eigen::Isometry3d& T_OinA, const Eigen::Isometry3d& T_GinA,
	                      double table_z_mm) const;
	bool reachAndVerify(RetrievalResult& r, hw::ArmDevice& arm,
	                    const std::function<std::optional<Eigen::Isometry3d>()>& reobserve,
	                    Timeline& timeline) const;
	/** T_GinO of the model's grasp turned by @p turn_deg about O's z axis. */
	Eigen::Isometry3d graspInObject(double turn_deg) const;
	/** The first feasible grasp turn (0, +s, −s, +2s, …); fills T_GinA, joints and reasons. */
	bool planGrasp(RetrievalResult& r, double table_z_mm) const;
	/** Joints of the pre-grasp pose: approach_mm back along z_G, else approach_mm above. */
	std::optional<arm::RtxJoints> preGraspJoints(const Eigen::Isometry3d& T_GinA) const;
	std::optional<arm::RtxJoints> solve(const Eigen::Isometry3d& T_GinA) const;
	void moveTo(hw::ArmDevice& arm, const arm::RtxJoints& j, Timeline& timeline) const;
	const MissionOptions& o_;
	const model::WireFrame& target_;
	arm::AnalyticIk ik_;
};

}  // namespace mrolr::mission
