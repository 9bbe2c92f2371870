#pragma once
/** Putting the retrieved object on board (thesis 7.0: the arm should "pick up the object and place
 * it on board MROLR"): an arm motion planned by the robot from what it knows of its own build —
 * the RTX's body (arm/ArmBody.h) at the calibrated mount, the base's deck and the head's mast
 * ([labmate] deck_height_m, mast_*; base/LabmateModel.h) — and the object's model held at the
 * grasp it was taken with.
 *
 * Candidate spots on the deck (rearmost first, then nearest the arm's column; the object upright,
 * turned in steps about the vertical) are solved by the analytic IK; a spot is taken when every
 * pose of the whole motion is free, tested every check_step_mm of travel:
 *   carry: straight up the column to the travel height, swing over the spot, down until the
 *          object's bottom is drop_mm above the deck, or as far as the arm clears the deck (with
 *          a side grasp the links stand at the grasp's height; at most kMaxRaise_mm higher);
 *   leave (jaws open): straight up to the travel height, swing back to the parked joints.
 * Free means: no arm box, the open finger plates included (but the column and its carriage, which
 * stand on the deck), within margin_mm of the deck or the mast; no two boxes of the arm that are
 * not joined meeting (arm/BodyCollision.h); no point of the held object inside an arm box, the
 * mast or the deck (it never comes lower than drop_mm / 2 above the deck). C0 frame, mm. */
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/ArmBody.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/model/WireFrame.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** The planned motion (report.json `retrieval.place`). */
struct PlacePlan
{
	bool found = false;
	std::string reason;  ///< why no spot was found (the nearest candidate's first contact)
	std::vector<arm::RtxJoints> carry;  ///< waypoints from the lifted pose; the last puts it down
	std::vector<arm::RtxJoints> leave;  ///< after the jaws open; the last is the parked pose
	/** The object's origin (its footprint's centre) on the deck under the release pose. */
	Eigen::Vector3d p_spotInC0_mm = Eigen::Vector3d::Zero();
	double yaw_deg = 0;           ///< its x axis from C0's z towards C0's x
	double drop_mm = 0;           ///< its bottom above the deck when the jaws open
	int candidates = 0;           ///< spots × turns on the deck
	int solved = 0;               ///< of those with an IK solution
	int tested_poses = 0;         ///< arm poses tested for contact
	double compute_s = 0;
};

/** What putting the object on board did (report.json `retrieval.place`). */
struct PlaceResult
{
	bool attempted = false;  ///< a plan was found and the arm began to move
	bool placed = false;     ///< the jaws opened with the object over its spot on the deck
	std::string reason;      ///< why not (no plan, the arm blocked, the object lost before)
	PlacePlan plan;
	double width_before_mm = 0;  ///< jaw distance just before opening
};

class DeckPlacement
{
 public:
	/** @p target: the held object's model (O, mm); @p T_C0inA_mm: the arm's mount (calibrated). */
	DeckPlacement(const MissionOptions& o, const model::WireFrame& target,
	              const Eigen::Isometry3d& T_C0inA_mm);

	/** The first free motion from @p lifted (object held at @p T_GinO) to a spot on the deck and
	 * back to @p parked. */
	PlacePlan plan(const arm::RtxJoints& lifted, const Eigen::Isometry3d& T_GinO_mm,
	               const arm::RtxJoints& parked) const;

	/** The first contact of the arm at @p j ("" when free); with @p T_GinO_mm, the object held
	 * there too, allowed down to @p object_floor_mm above the deck. */
	std::string contactAt(const arm::RtxJoints& j, const std::optional<Eigen::Isometry3d>& T_GinO_mm,
	                      double object_floor_mm) const;

	/** The first contact on the straight joint-space move @p a → @p b (tested every
	 * check_step_mm, both ends included); counts the tested poses in @p tested. */
	std::string contactAlong(const arm::RtxJoints& a, const arm::RtxJoints& b,
	                         const std::optional<Eigen::Isometry3d>& T_GinO_mm,
	                         double object_floor_mm, int& tested) const;

	/** The deck's slab (its top face is the deck) and the mast, C0 (mm). */
	const arm::PlacedBox& deck() const { return deck_; }
	const arm::PlacedBox& mast() const { return mast_; }

 private:
	struct Spot
	{
		Eigen::Vector3d p_inC0_mm;
		double yaw_deg;
	};
	std::vector<Spot> spots() const;
	/** The whole motion through the place pose @p down (the object at the spot), or the reason
	 * it is not free. */
	std::string motionThrough(const arm::RtxJoints& lifted, const arm::RtxJoints& down,
	                          const arm::RtxJoints& parked, const Eigen::Isometry3d& T_GinO_mm,
	                          PlacePlan& plan) const;
	Eigen::Isometry3d T_OinC0At(const Spot& s) const;

	const MissionOptions& o_;
	arm::RtxKinematics kin_;
	arm::AnalyticIk ik_;
	std::vector<arm::BodyBox> body_;
	std::vector<std::pair<size_t, size_t>> self_pairs_;
	Eigen::Isometry3d T_C0inA_, T_AinC0_;
	arm::PlacedBox deck_, mast_;
	double deck_top_y_mm_ = 0;               ///< the deck's top along C0's y
	std::vector<Eigen::Vector3d> points_O_;  ///< the held object's solid, sampled (O)
	double footprint_radius_mm_ = 0;         ///< largest horizontal reach of points_O_ from O
	double bottom_mm_ = 0;                   ///< the lowest of points_O_ along O's z
};

}  // namespace mrolr::mission
