// Oriented boxes overlap exactly when they share a point: the separating-axis test against a dense
// sampling of one box, over random pairs; and the arm's self-collision pairs skip its joints.
#include <mrolr/arm/BodyCollision.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr;

namespace
{
arm::PlacedBox randomBox(std::mt19937& rng)
{
	std::uniform_real_distribution<double> size(2.0, 12.0), at(-10.0, 10.0), angle(-M_PI, M_PI);
	arm::PlacedBox b;
	b.half_mm = {size(rng), size(rng), size(rng)};
	b.T_BoxInRef.linear() = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ()) *
	                         Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()) *
	                         Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()))
	                            .toRotationMatrix();
	b.T_BoxInRef.translation() = Eigen::Vector3d(at(rng), at(rng), at(rng)) * 2.0;
	return b;
}

/** Whether a grid of @p a's volume, @p step_mm apart, has a point inside @p b. */
bool sampledOverlap(const arm::PlacedBox& a, const arm::PlacedBox& b, double step_mm)
{
	const Eigen::Isometry3d into_b = b.T_BoxInRef.inverse();
	for (double x = -a.half_mm.x(); x <= a.half_mm.x(); x += step_mm)
		for (double y = -a.half_mm.y(); y <= a.half_mm.y(); y += step_mm)
			for (double z = -a.half_mm.z(); z <= a.half_mm.z(); z += step_mm)
			{
				const Eigen::Vector3d q = into_b * (a.T_BoxInRef * Eigen::Vector3d(x, y, z));
				if ((q.cwiseAbs() - b.half_mm).maxCoeff() <= 0) return true;
			}
	return false;
}
}  // namespace

TEST(BodyCollision, BoxesOverlapExactlyWhenASampledPointIsInBoth)
{
	std::mt19937 rng(7);
	int overlapping = 0, apart = 0;
	for (int k = 0; k < 400; ++k)
	{
		const auto a = randomBox(rng), b = randomBox(rng);
		// a sampled point of both ⇒ overlap; the boxes shrunk by 1 mm overlap ⇒ a ball of 1 mm
		// lies in both, and so does a point of the 0.5 mm grid
		if (sampledOverlap(a, b, 0.5))
		{
			EXPECT_TRUE(arm::boxesOverlap(a, b, 0)) << k;
		}
		arm::PlacedBox a1 = a, b1 = b;
		a1.half_mm.array() -= 1.0, b1.half_mm.array() -= 1.0;
		if (arm::boxesOverlap(a1, b1, 0))
		{
			EXPECT_TRUE(sampledOverlap(a, b, 0.5)) << k;
		}
		(arm::boxesOverlap(a, b, 0) ? overlapping : apart)++;
	}
	EXPECT_GT(overlapping, 40);  // both kinds of pair were drawn
	EXPECT_GT(apart, 40);
}

TEST(BodyCollision, AMarginGrowsTheFirstBox)
{
	arm::PlacedBox a, b;
	a.half_mm = b.half_mm = {10, 10, 10};
	b.T_BoxInRef.translation() = Eigen::Vector3d(25, 0, 0);  // 5 mm apart
	EXPECT_FALSE(arm::boxesOverlap(a, b, 4.9));
	EXPECT_TRUE(arm::boxesOverlap(a, b, 5.1));
}

TEST(BodyCollision, SelfPairsSkipJointsAndKeepTheHandAgainstTheColumn)
{
	const auto body = arm::rtxBody(arm::RtxOptions(), arm::GraspFeasibilityOptions(), arm::MarkerOptions());
	const auto pairs = arm::selfCollisionPairs(body);
	auto has = [&](int fa, int fb)
	{
		for (const auto& [i, j] : pairs)
			if ((body[i].frame == fa && body[j].frame == fb) || (body[i].frame == fb && body[j].frame == fa))
				return true;
		return false;
	};
	EXPECT_TRUE(has(0, 6));   // the hand against the column
	EXPECT_TRUE(has(2, 6));   // and against the upper arm
	EXPECT_TRUE(has(0, 3));   // the forearm against the column
	EXPECT_FALSE(has(0, 1));  // the carriage slides on the column
	EXPECT_FALSE(has(2, 3));  // the elbow
	EXPECT_FALSE(has(3, 6));  // the wrist
	EXPECT_FALSE(has(6, 6));  // one rigid hand
	// the parked arm (column at the top, stretched out) touches nothing of itself
	const arm::RtxKinematics kin{arm::RtxOptions()};
	const auto placed = arm::placeBody(body, kin, arm::RtxJoints(), Eigen::Isometry3d::Identity());
	EXPECT_FALSE(arm::firstSelfContact(placed, pairs, 5.0));
}
