#pragma once
/** Retrieval of a recognised object with the docked RTX arm (thesis 6.6–6.7, 7.2.2):
 *   T_OinA = T_C0inA · T_OinC0 (eq 6.7.1, T_C0inA the nominal [arm_mount] until setMount() gives
 *   the one calibrated where the robot stands, DockCalibration.h),
 *   T_GinA = T_OinA · T_GinO (the model's grasp line),
 * the grasp is checked (reach, opening, table, arm/GraspFeasibility.h, and a reachable pre-grasp
 * pose) before the arm moves; the arm goes to a pre-grasp pose approach_mm back along z_G (or above
 * the grasp when that is out of reach), the head fixates the object's estimated centre and
 * recognises it again in a new stereo pair, the grasp is recomputed from that pose (visual
 * verification, beyond the thesis's open loop; a correction above max_grasp_correction_mm is
 * refused and reported), then the gripper closes and the arm lifts. The robot judges the grasp by
 * its gripper's encoder: it holds the object while the jaws stay apart by at least
 * min_held_width_mm after closing and after the lift. An unreachable or infeasible grasp is
 * reported with its reasons and the arm never moves.
 */
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/SelfModel.h>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace mrolr::mission
{
/** A recognition of the object: its pose in C0 (mm) and, when the answer was ambiguous
 * (recog::RecognitionResult::ambiguous), every pose it supported about equally, the best first. */
struct Sighting
{
	Eigen::Isometry3d T_OinC0_mm = Eigen::Isometry3d::Identity();
	std::vector<Eigen::Isometry3d> poses_C0_mm;  ///< empty: not ambiguous
	bool ambiguous() const { return poses_C0_mm.size() > 1; }
};

/** The sighting of a search's answer: its pose in C0 and, if ambiguous, all of its poses in C0. */
Sighting sightingOf(const SearchResult& s);

/** What the retrieval did about an ambiguous pose (report.json `retrieval.ambiguity`). */
struct AmbiguityHandling
{
	enum class Resolution
	{
		None,             ///< the pose was not ambiguous
		GraspFitsAll,     ///< one grasp is the same grip on every pose
		LookedAgain,      ///< the verification view recognised it unambiguously
		StillAmbiguous    ///< after looking again (or without a second look): the best pose
	};
	Resolution resolution = Resolution::None;
	int poses = 0;          ///< poses of the first recognition
	int poses_fitted = 0;   ///< of those the planned grasp grips the same way
	static const char* name(Resolution r);
};

struct RetrievalResult
{
	bool attempted = false;  ///< the arm moved
	bool feasible = false;
	std::vector<std::string> reasons;                          ///< why not feasible / what failed
	Eigen::Isometry3d T_OinA = Eigen::Isometry3d::Identity();  ///< mm, from the first recognition
	Eigen::Isometry3d T_GinA = Eigen::Isometry3d::Identity();  ///< grasp actually used, mm
	double grasp_turn_deg = 0;  ///< turn of the model's grasp about O's vertical axis
	Eigen::Isometry3d T_GinO = Eigen::Isometry3d::Identity();  ///< that grasp in O, mm
	arm::RtxJoints joints;      ///< joint solution of the grasp
	bool verified = false;      ///< the re-observation recognised the object
	double correction_mm = 0;   ///< |t(T_GinA corrected) − t(T_GinA first)|
	double correction_deg = 0;
	bool correction_applied = false;  ///< the grasp used is the verified one
	bool correction_refused = false;  ///< verified, but beyond max_grasp_correction_mm
	/** The applied correction's way from the first pre-grasp to the verified one (Retrieval::
	 * crossing): the verified pre-grasp, or above the first, above the verified, and down. */
	std::vector<arm::RtxJoints> correction_route;
	/** The object pose (C0, mm) the grasp was first planned on (recognised, plus any injected
	 * error) and the one the verification recognised. */
	Eigen::Isometry3d T_OinC0_first_mm = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d T_OinC0_verified_mm = Eigen::Isometry3d::Identity();
	/** The stereo pair T_OinC0_first_mm was recognised in (C0 of that moment, which the base keeps
	 * until the lift); none for a simulated scene. */
	std::optional<uint64_t> frame;
	double width_closed_mm = 0;  ///< jaw distance right after closing
	double width_lifted_mm = 0;  ///< jaw distance after the lift
	bool retrieved = false;      ///< the robot believes it holds the object (jaw width)
	AmbiguityHandling ambiguity;
};

class Retrieval
{
 public:
	/** A new recognition of the object by the head, given the current estimate of T_OinC0 (mm)
	 * to look at; nothing when not recognised. */
	using Reobserve = std::function<std::optional<Sighting>(const Eigen::Isometry3d&)>;
	Retrieval(const MissionOptions& o, const model::WireFrame& target);
	/** The grasp of the object seen as @p first. An ambiguous sighting (beyond the thesis) is
	 * handled before the gripper closes: when the planned grasp grips every pose of it the same
	 * way (within kSameGrip_mm and kSameGrip_deg, the jaws' two ways round included) it is kept;
	 * otherwise the verification view's recognition decides, and if that too is ambiguous the
	 * best-supported pose is taken; result.ambiguity says which. */
	RetrievalResult run(const Sighting& first, double table_top_height_m, hw::ArmDevice& arm,
	                    const Reobserve& reobserve, Timeline& timeline) const;
	/** Two grasps are the same grip when this close (a millimetre-level pose difference between
	 * the rival poses of a nearly symmetric object is within the jaws' compliance and the
	 * verification's correction). */
	static constexpr double kSameGrip_mm = 10, kSameGrip_deg = 10;
	/** How many of @p poses_C0_mm the grasp @p T_GinA grips as it does the pose it was planned
	 * on (a turn of the model's grasp by the yaw search's steps, or the jaws turned round). */
	int posesGrippedAlike(const Eigen::Isometry3d& T_GinA, double turn_deg,
	                      const std::vector<Eigen::Isometry3d>& poses_C0_mm) const;
	/** The grasp (A, mm) of the model's grasp line turned by @p turn_deg, object at
	 * @p T_OinC0_mm (eq 6.7.1). */
	Eigen::Isometry3d graspAt(const Eigen::Isometry3d& T_OinC0_mm, double turn_deg) const;
	/** The verification view is taken from the first of the pre-grasp pose and poses above it
	 * (every approach_mm up to the column's top) from which @p self says the arm leaves the
	 * object in view (@p self outlives this). */
	void viewPast(const SelfModel& self) { self_ = &self; }
	/** From now on the grasp chain uses @p T_C0inA_mm (the calibrated mount). */
	void setMount(const Eigen::Isometry3d& T_C0inA_mm) { T_C0inA_ = T_C0inA_mm; }
	const Eigen::Isometry3d& mount() const { return T_C0inA_; }
	/** The table top's height in A (mm) under the object at @p p_OinC0_mm, for a top
	 * @p top_height_m above the floor (A may stand tilted on the base: the dock's error). */
	double tableZinA(double top_height_m, const Eigen::Vector3d& p_OinC0_mm) const;
	/** Whether a grasp of the object at @p T_OinC0_mm (C0 where the base stands, or would stand)
	 * is feasible, without moving the arm; @p reasons says why not (the docking planner's test). */
	bool feasibleAt(const Eigen::Isometry3d& T_OinC0_mm, double table_top_height_m,
	                std::vector<std::string>* reasons = nullptr) const;

 private:
	arm::GraspCheck check(const Eigen::Isometry3d& T_OinA, const Eigen::Isometry3d& T_GinA,
	                      double table_z_mm) const;
	bool reachAndVerify(RetrievalResult& r, hw::ArmDevice& arm, const Reobserve& reobserve,
	                    Timeline& timeline) const;
	/** Whether the planned grasp grips every pose of an ambiguous @p first alike. */
	void judgeAmbiguity(RetrievalResult& r, const Sighting& first, Timeline& timeline) const;
	/** An ambiguity left open is settled by the verification view @p seen, or stays open. */
	void lookedAgain(RetrievalResult& r, const std::optional<Sighting>& seen, Timeline& timeline) const;
	/** Recomputes the grasp from the verified pose and applies it unless refused. */
	void correct(RetrievalResult& r, const Eigen::Isometry3d& T_OinC0_mm, Timeline& timeline) const;
	/** The turn of the grasp at @p T_OinA nearest in rotation to the planned grasp (a symmetric
	 * object may be recognised turned by a multiple of grasp_yaw_search_deg). */
	double nearestTurn(const RetrievalResult& r, const Eigen::Isometry3d& T_OinA) const;
	/** T_GinO of the model's grasp turned by @p turn_deg about O's z axis. */
	Eigen::Isometry3d graspInObject(double turn_deg) const;
	/** The first feasible grasp turn (0, +s, −s, +2s, …) with a solution reached straight from
	 * its pre-grasp on one arm branch; fills T_GinA, joints and reasons. */
	bool planGrasp(RetrievalResult& r, double table_z_mm) const;
	/** Joints of the pre-grasp pose: approach_mm back along z_G, else approach_mm above; the
	 * solution nearest @p near. */
	std::optional<arm::RtxJoints> preGraspJoints(const Eigen::Isometry3d& T_GinA,
	                                             const arm::RtxJoints& near) const;
	/** The IK solution of @p T_GinA nearest @p near in joints. */
	std::optional<arm::RtxJoints> solve(const Eigen::Isometry3d& T_GinA, const arm::RtxJoints& near) const;
	void moveTo(hw::ArmDevice& arm, const arm::RtxJoints& j, Timeline& timeline) const;
	/** The hand moved along the straight line (and the shortest turn) from where the arm is to
	 * @p j's pose, through IK solutions every kStraightStep_mm, each the nearest in joints to the
	 * one before: the fingers come in along their axis instead of sweeping sideways as a
	 * joint-space move does; one arm move of simulated time. */
	void moveStraight(hw::ArmDevice& arm, const arm::RtxJoints& j, Timeline& timeline) const;
	/** The joints of that line, @p to last; nothing when a point of it has no IK solution or the
	 * arm would have to change branch on the way (the joint-space move then follows). */
	std::optional<std::vector<arm::RtxJoints>> straightPath(const arm::RtxJoints& from,
	                                                        const arm::RtxJoints& to) const;
	/** From the pre-grasp at joints @p from to the one at @p to: the targets, each reached
	 * straight from the one before on one arm branch. Two pre-grasps level within kLevel_mm are
	 * joined straight; otherwise (or when that line has no branch) the hand goes up to
	 * approach_mm above the higher, across, and down, so the fingers never cut through the
	 * object between a pre-grasp beside it and one above it. Nothing when neither way exists. */
	std::optional<std::vector<arm::RtxJoints>> crossing(const arm::RtxJoints& from,
	                                                    const arm::RtxJoints& to) const;
	static constexpr double kLevel_mm = 10;
	/** The column (d1, mm) for the swing to @p above: the wrist centre high enough that the hand,
	 * d6 from it in any direction, passes kSwingClearance_mm over the object's top (its model at
	 * T_OinA) while the wrist turns; never below @p above's own. */
	double swingColumnMm(const RetrievalResult& r, const arm::RtxJoints& above) const;
	static constexpr double kSwingClearance_mm = 30;
	static constexpr double kStraightStep_mm = 10;
	static constexpr double kStraightRadius_mm = 200;  ///< a turn counted as the fingertips' travel
	const MissionOptions& o_;
	/** Closes the gripper, lifts, and judges from the jaw width whether it holds the object. */
	void closeAndLift(RetrievalResult& r, hw::ArmDevice& arm, Timeline& timeline) const;
	const model::WireFrame& target_;
	arm::AnalyticIk ik_;
	arm::RtxKinematics kin_;
	Eigen::Isometry3d T_C0inA_;
	const SelfModel* self_ = nullptr;
	/** Joints of the verification view: the pre-grasp @p pre, or a pose above it. */
	arm::RtxJoints viewingJoints(const RetrievalResult& r, const arm::RtxJoints& pre) const;
};

}  // namespace mrolr::mission
