#include <mrolr/arm/RtxKinematics.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/CMatrixFixed.h>

namespace mrolr::arm
{
namespace
{
Eigen::Isometry3d toEigen(const mrpt::poses::CPose3D& p)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.matrix() = p.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
	return T;
}
}  // namespace

RtxKinematics::RtxKinematics(const RtxOptions& options) : options_(options) {}

mrpt::kinematics::CKinematicChain RtxKinematics::chain(const RtxJoints& j, double scale) const
{
	const auto& o = options_;
	const double half_pi = M_PI / 2;
	mrpt::kinematics::CKinematicChain c;
	// addLink(theta, d, a, alpha, is_prismatic); A1 carries both the fixed q1 and the column d1.
	c.addLink(j.q(1), j.d1_mm * scale, 0, 0, true);
	c.addLink(j.q(2), 0, o.a2_mm * scale, 0, false);
	c.addLink(j.q(3), 0, o.a3_mm * scale, 0, false);
	c.addLink(j.q(4), 0, 0, half_pi, false);
	c.addLink(j.q(5), 0, 0, half_pi, false);
	c.addLink(j.q(6), o.d6_mm * scale, 0, 0, false);
	return c;
}

std::vector<Eigen::Isometry3d> RtxKinematics::linkFrames(const RtxJoints& j) const
{
	std::vector<mrpt::poses::CPose3D> poses;
	chain(j).recomputeAllPoses(poses);
	std::vector<Eigen::Isometry3d> out;
	out.reserve(poses.size());
	for (const auto& p : poses) out.push_back(toEigen(p));
	return out;
}

Eigen::Isometry3d RtxKinematics::T06(const RtxJoints& j) const
{
	return linkFrames(j).back();
}

Jacobian6 RtxKinematics::jacobian(const RtxJoints& j) const
{
	const auto T = linkFrames(j);
	const Eigen::Vector3d p_end = T[6].translation();
	Jacobian6 J = Jacobian6::Zero();
	J.block<3, 1>(0, 0) = T[0].linear().col(2);  // prismatic d1 along z0
	for (int k = 2; k <= 6; ++k)                 // revolute q_k about z_{k-1}
	{
		const Eigen::Vector3d z = T[static_cast<size_t>(k - 1)].linear().col(2);
		const Eigen::Vector3d p = T[static_cast<size_t>(k - 1)].translation();
		J.block<3, 1>(0, k - 1) = z.cross(p_end - p);
		J.block<3, 1>(3, k - 1) = z;
	}
	return J;
}

}  // namespace mrolr::arm
