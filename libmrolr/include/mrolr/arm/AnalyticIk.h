#pragma once
/** Closed-form inverse kinematics of the UMI RTX (thesis B.3.3.1, compute_xyz, generalised): the
 * wrist centre p_w = p − d6·z6 fixes the column height d1 = p_w.z; the planar shoulder–elbow pair
 * reaches the wrist's horizontal position in two elbow configurations; the wrist yaw q4, pitch q5
 * and roll q6 then give the orientation, again in two configurations (q5 and −q5). Every
 * combination, with every 360° turn of a joint that stays within the limits, is returned. */

#include <mrolr/arm/MotorCounts.h>
#include <mrolr/arm/RtxJoints.h>
#include <mrolr/arm/RtxOptions.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace mrolr::arm
{
/** One joint configuration reaching the requested pose. */
struct IkSolution
{
	RtxJoints joints;
	MotorCounts counts{};        ///< real-valued; round with roundCounts()
	bool elbow_left = true;      ///< q3 <= 0 (compute_xyz's default "LH" configuration)
	bool wrist_flipped = false;  ///< q5 < 0
};

/** Why a candidate was rejected: either the pose itself (@ref pose_reason set, no branch), or one
 * elbow/wrist branch whose first motor out of range is @ref motor. Kept as values and formatted
 * only on demand, so that a solve with rejected branches costs no text. */
struct IkRejection
{
	std::string pose_reason;  ///< "wrist radius 510 mm outside limit [...]"; empty for a branch
	bool elbow_left = true;
	bool wrist_flipped = false;
	Motor motor = Motor::Column;  ///< the first motor out of range (of the turn nearest zero)
	double count = 0;             ///< its count
	CountRange limit;             ///< and its limit
	/** "elbow right, wrist normal: elbow count 1700.2 outside limit [-1490, 1490]". */
	std::string text() const;
};

/** Every solution, and why the rejected candidates were rejected. */
struct IkResult
{
	std::vector<IkSolution> solutions;
	std::vector<IkRejection> rejected;
	/** "" when solutions exist; otherwise every rejection's text() joined by "; ". */
	std::string reason() const;
};

class AnalyticIk
{
 public:
	explicit AnalyticIk(const RtxOptions& options = RtxOptions());

	/** All solutions for the gripper pose T06 (mm, frame 0 = arm base A) within the joint limits.
	 * A pose outside the column range or the wrist radius gives no solution and one reason naming
	 * that limit. Never throws for a finite pose. */
	IkResult solve(const Eigen::Isometry3d& T06) const;

	/** As solve(), but throws UnreachableError with the reason when there is no solution. */
	std::vector<IkSolution> solveAll(const Eigen::Isometry3d& T06) const;

 private:
	RtxOptions o_;
};

}  // namespace mrolr::arm
