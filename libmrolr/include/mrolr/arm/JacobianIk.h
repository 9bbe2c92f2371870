#pragma once
/** The general iterative inverse kinematics of thesis B.3.3: q ← q + J⁺·e with the manipulator
 * Jacobian J (RtxKinematics::jacobian) and the pose error e, ported there from Corke's Robotics
 * Toolbox. Here J⁺ is the damped least-squares inverse Σ σᵢ/(σᵢ² + λ²)·vᵢuᵢᵀ, with λ growing only
 * when the smallest singular value falls below a threshold (Nakamura–Hanafusa / Chiaverini), so the
 * iteration stays bounded near singularities and is a plain pseudo-inverse elsewhere. */

#include <mrolr/arm/RtxKinematics.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::arm
{
/** Options of the damped least-squares solver, section [rtx_jacobian_ik] of config/arm_rtx.ini. */
struct JacobianIkOptions
{
	int max_iterations = 200;
	double tolerance_mm = 1e-7;    ///< position error at convergence
	double tolerance_rad = 1e-10;  ///< orientation error (angle of R_target·Rᵀ) at convergence
	double length_scale_mm = 254;  ///< position rows are divided by this to mix with radians
	double damping_max = 0.05;     ///< λ at an exact singularity (dimensionless)
	double singular_threshold = 0.05;  ///< σ_min below which damping starts
	double max_step_rad = 0.35;  ///< largest joint change per iteration (d1: × length_scale_mm)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

struct JacobianIkResult
{
	bool converged = false;
	RtxJoints joints;  ///< last iterate (angles wrapped to (−π, π])
	int iterations = 0;
	double position_error_mm = 0;
	double orientation_error_rad = 0;
};

class JacobianIk
{
 public:
	explicit JacobianIk(const RtxOptions& rtx = RtxOptions(),
	                    const JacobianIkOptions& options = JacobianIkOptions());

	/** Iterates from @p seed towards the gripper pose @p T06 (mm, frame 0); q1 stays at the seed's
	 * value. Joint limits are not imposed during the iteration: check the result with
	 * requireWithinLimits(). */
	JacobianIkResult solve(const Eigen::Isometry3d& T06, const RtxJoints& seed) const;

 private:
	RtxKinematics kin_;
	JacobianIkOptions opt_;
};

}  // namespace mrolr::arm
