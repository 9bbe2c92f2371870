// The body between a can's rims is sampled: points at every height between them, on the radius
// interpolated between the rims; circles on different axes are not joined.
#include <mrolr/arm/SolidSampling.h>

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
model::Conic3 circle(const Eigen::Vector3d& c, double r)
{
	model::Conic3 k;
	k.centre = c, k.normal = Eigen::Vector3d::UnitZ(), k.major = Eigen::Vector3d::UnitX();
	k.a = k.b = r, k.t1 = 0, k.t2 = 2 * M_PI;
	return k;
}
}  // namespace

TEST(SolidSampling, TheBodyBetweenCoaxialRimsIsSampledOnTheInterpolatedRadius)
{
	model::WireFrame can;
	can.conics = {circle({0, 0, 120}, 30), circle({0.5, 0, 0}, 34)};
	const auto body = arm::sampleRevolutionSurfaces(can, Eigen::Isometry3d::Identity(), 4);
	ASSERT_FALSE(body.empty());
	int near_grasp_height = 0;
	for (const auto& p : body)
	{
		ASSERT_GT(p.z(), 0);
		ASSERT_LT(p.z(), 120);
		const double f = p.z() / 120, r = 34 + f * (30 - 34);
		const Eigen::Vector2d c(0.5 * (1 - f), 0);
		EXPECT_NEAR((p.head<2>() - c).norm(), r, 1e-9);
		if (std::abs(p.z() - 60) < 4) ++near_grasp_height;
	}
	EXPECT_GT(near_grasp_height, 40);  // a whole ring about the grasp height
	// sampleSolid adds them to the rims' own samples
	EXPECT_GT(arm::sampleSolid(can, Eigen::Isometry3d::Identity(), 4).size(), body.size());
}

TEST(SolidSampling, CirclesOnDifferentAxesOrAlonePartialOnesAreNotJoined)
{
	model::WireFrame two;
	two.conics = {circle({0, 0, 0}, 30), circle({100, 0, 100}, 30)};
	EXPECT_TRUE(arm::sampleRevolutionSurfaces(two, Eigen::Isometry3d::Identity(), 4).empty());
	model::WireFrame arc;
	arc.conics = {circle({0, 0, 0}, 30), circle({0, 0, 100}, 30)};
	arc.conics[1].t2 = M_PI;  // half a circle: no rim of a body
	EXPECT_TRUE(arm::sampleRevolutionSurfaces(arc, Eigen::Isometry3d::Identity(), 4).empty());
}
