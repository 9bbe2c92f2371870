#include <mrolr/arm/JacobianIk.h>
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/SVD>

#include <algorithm>
#include <iomanip>
#include <ostream>

namespace mrolr::arm
{
namespace
{
using Vector6 = Eigen::Matrix<double, 6, 1>;

/** Pose error [Δp / L; ω] with ω the rotation vector of R_target·Rᵀ (frame 0). */
Vector6 poseError(const Eigen::Isometry3d& target, const Eigen::Isometry3d& T, double L)
{
	Vector6 e;
	e.head<3>() = (target.translation() - T.translation()) / L;
	const Eigen::AngleAxisd aa(target.linear() * T.linear().transpose());
	e.tail<3>() = aa.angle() * aa.axis();
	return e;
}

/** Damped least-squares step J⁺e. Below the threshold ε the damping is
 * λ² = (1 − (σ_min/ε)²)·λ_max², scaled by min(1, |e|) so that it fades as the error vanishes and
 * the last iterations are plain Gauss–Newton steps (quadratic convergence even at a singularity).
 */
Vector6 dlsStep(const Jacobian6& J, const Vector6& e, const JacobianIkOptions& o)
{
	Eigen::JacobiSVD<Jacobian6> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
	const auto& s = svd.singularValues();
	const double smin = s[5], eps = o.singular_threshold;
	const double lambda2 = smin < eps ? (1 - (smin / eps) * (smin / eps)) * o.damping_max *
	                                        o.damping_max * std::min(1.0, e.norm())
	                                  : 0.0;
	Vector6 ue = svd.matrixU().transpose() * e;
	for (int i = 0; i < 6; ++i) ue[i] = s[i] > 1e-12 ? ue[i] * s[i] / (s[i] * s[i] + lambda2) : 0.0;
	return svd.matrixV() * ue;
}
}  // namespace

namespace
{
using O = JacobianIkOptions;

const util::OptionsBinder<O>& jacobianIkOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .integer("max_iterations", &O::max_iterations, 1, 1000000)
	    .number("tolerance_mm", &O::tolerance_mm, 0, 1e6)
	    .number("tolerance_rad", &O::tolerance_rad, 0, 10)
	    .number("length_scale_mm", &O::length_scale_mm, 1e-6, 1e6)
	    .number("damping_max", &O::damping_max, 0, 1e12)
	    .number("singular_threshold", &O::singular_threshold, 0, 1e12)
	    .number("max_step_rad", &O::max_step_rad, 1e-6, 10);
	return b;
}
}  // namespace

void JacobianIkOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& section)
{
	jacobianIkOptionsBinder().load(cfg, section, *this);
}

void JacobianIkOptions::dump(std::ostream& out) const
{
	out << std::setprecision(10);
	jacobianIkOptionsBinder().dump(out, *this);
}

JacobianIk::JacobianIk(const RtxOptions& rtx, const JacobianIkOptions& options)
    : kin_(rtx), opt_(options)
{
}

JacobianIkResult JacobianIk::solve(const Eigen::Isometry3d& T06, const RtxJoints& seed) const
{
	const double L = opt_.length_scale_mm;
	JacobianIkResult r;
	r.joints = seed;
	for (r.iterations = 0; r.iterations <= opt_.max_iterations; ++r.iterations)
	{
		const Vector6 e = poseError(T06, kin_.T06(r.joints), L);
		r.position_error_mm = e.head<3>().norm() * L;
		r.orientation_error_rad = e.tail<3>().norm();
		r.converged = r.position_error_mm <= opt_.tolerance_mm &&
		              r.orientation_error_rad <= opt_.tolerance_rad;
		if (r.converged || r.iterations == opt_.max_iterations) break;
		Jacobian6 J = kin_.jacobian(r.joints);
		J.topRows<3>() /= L;
		J.col(0) *= L;  // d1 in units of L, like the position rows
		Vector6 dq = dlsStep(J, e, opt_);
		const double biggest = dq.cwiseAbs().maxCoeff();
		if (biggest > opt_.max_step_rad) dq *= opt_.max_step_rad / biggest;
		dq[0] *= L;
		r.joints.setActive(r.joints.active() + dq);
	}
	for (size_t i = 1; i < 6; ++i) r.joints.q_rad[i] = mrpt::math::wrapToPi(r.joints.q_rad[i]);
	return r;
}

}  // namespace mrolr::arm
