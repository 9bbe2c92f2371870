#include <mrolr/base/LabmateModel.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using mrolr::base::LabmateModel;
using mrolr::base::LabmateOptions;
using mrolr::base::WheelControl;

namespace
{
const LabmateModel kModel{};  // D1 = 0.3 m, fraction 0.14

template <class F, int N>
Eigen::Matrix<double, 3, N> centralDiff(F f, Eigen::Matrix<double, N, 1> x, double h)
{
	Eigen::Matrix<double, 3, N> J;
	for (int i = 0; i < N; ++i)
	{
		auto a = x, b = x;
		a[i] += h;
		b[i] -= h;
		J.col(i) = (f(a) - f(b)) / (2 * h);
	}
	return J;
}
}  // namespace

TEST(LabmateModel, StraightLineFollowsTheHeading)
{
	const Eigen::Vector3d x0(1.0, -0.5, 0.3);
	const auto x1 = kModel.move(x0, {0.1, 0.1, 2.0});
	EXPECT_NEAR(x1[0], 1.0 + 0.2 * std::cos(0.3), 1e-15);
	EXPECT_NEAR(x1[1], -0.5 + 0.2 * std::sin(0.3), 1e-15);
	EXPECT_DOUBLE_EQ(x1[2], 0.3);
}

TEST(LabmateModel, RotationInPlaceKeepsThePosition)
{
	const Eigen::Vector3d x0(0.4, 0.7, -1.0);
	const auto x1 = kModel.move(x0, {0.05, -0.05, 3.0});
	EXPECT_NEAR((x1 - x0).head<2>().norm(), 0, 1e-15);
	// θ = (v1 − v2) Δt / (2 D1) = 0.1 · 3 / 0.6 = 0.5 rad, towards x (left).
	EXPECT_NEAR(x1[2], -0.5, 1e-15);
	EXPECT_NEAR(kModel.rotationControl(-0.5).dt_s * 0.05 / 0.3, 0.5, 1e-12);
}

TEST(LabmateModel, ArcStaysOnItsCircle)
{
	// Turning left (v1 > v2): the centre is R = D1 (v1 + v2)/(v1 − v2) to the left (eq 4.54).
	const Eigen::Vector3d x0(0, 0, 0.2);
	const WheelControl u{0.12, 0.08, 5.0};
	const double R = 0.3 * 0.2 / 0.04;
	const Eigen::Vector2d centre(-R * std::sin(0.2), R * std::cos(0.2));  // (z, x)
	const auto x1 = kModel.move(x0, u);
	EXPECT_NEAR((x1.head<2>() - centre).norm(), R, 1e-12);
	EXPECT_NEAR(x1[2] - x0[2], 0.04 * 5 / 0.6, 1e-15);
	// Quarter circle from the origin facing z ends at (R, R) facing x.
	const WheelControl quarter{0.2, 0.1, M_PI / 2 * 0.6 / 0.1};
	const auto q = kModel.move(Eigen::Vector3d::Zero(), quarter);
	EXPECT_NEAR(q[0], 0.9, 1e-12);
	EXPECT_NEAR(q[1], 0.9, 1e-12);
	EXPECT_NEAR(q[2], M_PI / 2, 1e-15);
}

TEST(LabmateModel, ContinuousAsV1ApproachesV2)
{
	const Eigen::Vector3d x0(0.3, 0.2, 1.1);
	const auto straight = kModel.move(x0, {0.1, 0.1, 2});
	const auto Gs = kModel.jacobianControl(x0, {0.1, 0.1, 2});
	for (double d : {1e-1, 1e-3, 1e-5, 1e-8, 1e-12, 0.0})
	{
		const WheelControl u{0.1 + d, 0.1 - d, 2};
		// Lipschitz in d: θ = 2d Δt / (2 D1) ≈ 6.7 d dominates.
		EXPECT_LT((kModel.move(x0, u) - straight).norm(), 7 * d + 1e-15) << d;
		EXPECT_LT((kModel.jacobianControl(x0, u) - Gs).norm(), 40 * d + 1e-14) << d;
		EXPECT_TRUE(kModel.move(x0, u).allFinite());
	}
	// Either side of the series/closed-form switch at θ = 1e-2 agrees.
	const double dv = 1e-2 * 0.6;  // θ = dv Δt / (2 D1) = 1e-2 at Δt = 1 s
	const auto lo = kModel.jacobianControl(x0, {0.1 + dv * (1 - 1e-9), 0.1, 1});
	const auto hi = kModel.jacobianControl(x0, {0.1 + dv * (1 + 1e-9), 0.1, 1});
	EXPECT_LT((lo - hi).norm(), 1e-10);
}

TEST(LabmateModel, JacobiansMatchCentralDifferences)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> pos(-3, 3), ang(-M_PI, M_PI), vel(-0.3, 0.3), dt(0.1, 4);
	for (int k = 0; k < 300; ++k)
	{
		const Eigen::Vector3d x(pos(rng), pos(rng), ang(rng));
		WheelControl u{vel(rng), vel(rng), dt(rng)};
		if (k % 3 == 0) u.v2_mps = u.v1_mps + 1e-7;  // near-straight
		const auto fx = [&](const Eigen::Vector3d& xv) { return kModel.move(xv, u); };
		const auto fu = [&](const Eigen::Vector2d& v) {
			return kModel.move(x, {v[0], v[1], u.dt_s});
		};
		const Eigen::Matrix3d Fn = centralDiff<decltype(fx), 3>(fx, x, 1e-6);
		const Eigen::Matrix<double, 3, 2> Gn =
		    centralDiff<decltype(fu), 2>(fu, Eigen::Vector2d(u.v1_mps, u.v2_mps), 1e-6);
		EXPECT_LT((kModel.jacobianState(x, u) - Fn).cwiseAbs().maxCoeff(), 1e-8);
		EXPECT_LT((kModel.jacobianControl(x, u) - Gn).cwiseAbs().maxCoeff(), 1e-7);
	}
}

TEST(LabmateModel, ProcessNoiseMatchesMonteCarlo)
{
	// Small noise so that first-order propagation is accurate: compare Q with the sample
	// covariance.
	LabmateOptions o;
	o.velocity_noise_fraction = 0.02;
	const LabmateModel m(o);
	const Eigen::Vector3d x0(0.5, -0.2, 0.7);
	for (const WheelControl u :
	     {WheelControl{0.1, 0.1, 2}, WheelControl{0.12, 0.07, 3}, WheelControl{0.05, -0.05, 4}})
	{
		std::mt19937 rng(11);
		std::normal_distribution<double> n(0, 1);
		const int N = 40000;
		Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
		const Eigen::Vector3d mean = m.move(x0, u);
		for (int i = 0; i < N; ++i)
		{
			WheelControl un = u;
			un.v1_mps += 0.02 * std::abs(u.v1_mps) * n(rng);
			un.v2_mps += 0.02 * std::abs(u.v2_mps) * n(rng);
			const Eigen::Vector3d d = m.move(x0, un) - mean;
			C += d * d.transpose() / N;
		}
		const Eigen::Matrix3d Q = m.processNoise(x0, u);
		// 40000 samples: sample variances within about 3 % (plus nonlinear bias).
		for (int i = 0; i < 3; ++i)
		{
			if (Q(i, i) < 1e-14) continue;
			EXPECT_NEAR(C(i, i) / Q(i, i), 1.0, 0.05) << i;
		}
		EXPECT_LT((C - Q).norm() / Q.norm(), 0.05);
	}
}

TEST(LabmateModel, ConfigErrorsNameTheKey)
{
	mrpt::config::CConfigFileMemory cfg(
	    std::string("[labmate]\nwheel_half_separation_m = 0.3\nvelocity_noise_fraction = abc\n"
	                "translation_speed_mps = 0.1\nrotation_wheel_speed_mps = 0.05\n"));
	LabmateOptions o;
	try
	{
		o.loadFromConfigFile(cfg, "labmate");
		FAIL() << "malformed value accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("velocity_noise_fraction"), std::string::npos);
		EXPECT_NE(std::string(e.what()).find("labmate"), std::string::npos);
	}
}

TEST(LabmateModel, ShippedConfigLoads)
{
	mrpt::config::CConfigFile cfg(std::string(MROLR_SOURCE_DIR) + "/config/labmate.ini");
	LabmateOptions o;
	o.loadFromConfigFile(cfg, "labmate");
	EXPECT_DOUBLE_EQ(o.velocity_noise_fraction, 0.14);
	EXPECT_GT(o.wheel_half_separation_m, 0);
}
