// The damped least-squares Jacobian IK of B.3.3, cross-checked with Orocos KDL's LMA solver.
#include "ArmTestUtil.h"

#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/JacobianIk.h>
#include <mrolr/arm/RtxKdl.h>

#include <gtest/gtest.h>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>

using namespace mrolr::arm;

namespace
{
/** Seed: the generating joints disturbed by up to ±0.3 rad and ±50 mm. */
RtxJoints nearby(const RtxJoints& j, std::mt19937& rng)
{
	std::uniform_real_distribution<double> u(-1, 1);
	RtxJoints s = j;
	s.d1_mm += 50 * u(rng);
	for (size_t i = 1; i < 6; ++i) s.q_rad[i] += 0.3 * u(rng);
	return s;
}
}  // namespace

TEST(ArmJacobianIk, ConvergesFromNearbySeedsAndAgreesWithKdlLma)
{
	std::mt19937 rng(7);
	const RtxKinematics kin;
	const JacobianIk ik;
	KDL::Chain chain = rtxKdlChain(kin.options(), 0, 0.001);  // metres, as KDL expects
	KDL::ChainIkSolverPos_LMA lma(chain, 1e-12, 500);
	KDL::ChainFkSolverPos_recursive fk(chain);
	int ours = 0, kdl = 0;
	for (int n = 0; n < 300; ++n)
	{
		const RtxJoints j = test::randomReachableJoints(rng);
		const Eigen::Isometry3d T = kin.T06(j);
		const RtxJoints seed = nearby(j, rng);
		const JacobianIkResult r = ik.solve(T, seed);
		if (r.converged)
		{
			++ours;
			EXPECT_LT(test::positionError(kin.T06(r.joints), T), 1e-6);
			EXPECT_LT(test::rotationError(kin.T06(r.joints), T), 1e-9);
		}
		KDL::JntArray out(6);
		if (lma.CartToJnt(toKdl(seed, 0.001), toKdl(T, 0.001), out) >= 0)
		{
			KDL::Frame F;
			fk.JntToCart(out, F);
			if (test::positionError(fromKdl(F, 0.001), T) < 1e-3) ++kdl;
			// Both solvers reproduce the same pose through independent FK implementations.
			EXPECT_LT(test::positionError(kin.T06(fromKdl(out, 0, 0.001)), fromKdl(F, 0.001)),
			          1e-6);
		}
	}
	EXPECT_GE(ours, 295);
	EXPECT_GE(kdl, 250);
}

TEST(ArmJacobianIk, AgreesWithTheAnalyticSolutionItConvergesTo)
{
	std::mt19937 rng(8);
	const RtxKinematics kin;
	const JacobianIk ik;
	const AnalyticIk analytic;
	for (int n = 0; n < 100; ++n)
	{
		const RtxJoints j = test::randomReachableJoints(rng);
		const Eigen::Isometry3d T = kin.T06(j);
		const JacobianIkResult r = ik.solve(T, nearby(j, rng));
		if (!r.converged) continue;
		double best = 1e9;
		for (const auto& s : analytic.solve(T).solutions)
			best = std::min(best, (s.joints.active() - r.joints.active()).cwiseAbs().maxCoeff());
		// A converged iterate within limits is one of the closed-form solutions.
		if (limitViolation(jointsToCounts(r.joints, kin.options()), kin.options()).empty())
		{
			EXPECT_LT(best, 1e-6);
		}
	}
}

TEST(ArmJacobianIk, StaysBoundedAtTheWristSingularity)
{
	// Gripper pointing straight down (q5 = 0): J loses rank; DLS still reaches the pose.
	const RtxKinematics kin;
	RtxJoints target;
	target.d1_mm = 600;
	target.q_rad = {0, 0.3, -0.8, 0.2, 0.0, 0.4};
	RtxJoints seed = target;
	seed.q_rad[4] = 0.2;
	seed.q_rad[3] = -0.1;
	const JacobianIkResult r = JacobianIk().solve(kin.T06(target), seed);
	EXPECT_TRUE(r.converged) << r.position_error_mm << " mm " << r.orientation_error_rad << " rad";
	EXPECT_LT(test::positionError(kin.T06(r.joints), kin.T06(target)), 1e-6);
	EXPECT_TRUE(r.joints.active().allFinite());
}

TEST(ArmJacobianIk, UnreachablePoseDoesNotConvergeAndReportsTheError)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation() = Eigen::Vector3d(2000, 0, 500);
	const JacobianIkResult r = JacobianIk().solve(T, RtxJoints());
	EXPECT_FALSE(r.converged);
	EXPECT_GT(r.position_error_mm, 1000);
	EXPECT_TRUE(r.joints.active().allFinite());
}
