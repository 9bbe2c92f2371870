// The top grasp from the segments' centroid (6.6.1) and the grasp feasibility checks (6.8, 7.2.2).
#include "ArmTestUtil.h"

#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/TopGrasp.h>

#include <mrpt/config/CConfigFile.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::arm;
using mrolr::model::Line3;
using ::testing::HasSubstr;

namespace
{
/** The 12 edges of an axis-aligned box of size (sx, sy, sz) mm standing on z = base_z. */
mrolr::model::WireFrame box(const Eigen::Vector3d& centre_xy, double sx, double sy, double sz,
                            double base_z)
{
	mrolr::model::WireFrame wf;
	const Eigen::Vector3d h(sx / 2, sy / 2, 0);
	Eigen::Vector3d c[8];
	for (int i = 0; i < 8; ++i)
		c[i] = Eigen::Vector3d(centre_xy.x() + ((i & 1) ? h.x() : -h.x()),
		                       centre_xy.y() + ((i & 2) ? h.y() : -h.y()),
		                       base_z + ((i & 4) ? sz : 0));
	const int e[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
	                      {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
	for (int k = 0; k < 12; ++k) wf.lines.push_back({k, c[e[k][0]], c[e[k][1]]});
	return wf;
}

const Eigen::Isometry3d kIdentity = Eigen::Isometry3d::Identity();

Eigen::Isometry3d topAt(const GripperPose& g)
{
	return poseFromGripper(g);
}
}  // namespace

TEST(ArmTopGrasp, CentroidOfMidpointsAndConicCentres)
{
	std::vector<Line3> lines = {{1, {0, 0, 0}, {10, 0, 0}}, {2, {0, 10, 0}, {0, 30, 0}}};
	mrolr::model::Conic3 c;
	c.centre = {3, 4, 6};
	EXPECT_TRUE(segmentCentroid(lines, {c})
	                .isApprox(Eigen::Vector3d((5 + 0 + 3) / 3.0, (0 + 20 + 4) / 3.0, 2)));
	EXPECT_THROW(segmentCentroid({}, {}), std::invalid_argument);
}

TEST(ArmTopGrasp, ApproachesFromAboveAcrossTheNarrowSide)
{
	// A 100 × 40 mm box, long along x: the fingers must close along y (yaw 0 closes along −y).
	const auto wf = box({400, 0, 0}, 100, 40, 60, 300);
	const GripperPose g = topGrasp(wf.lines, wf.conics);
	EXPECT_NEAR(g.pitch_deg, 90, 0);
	EXPECT_NEAR(g.p_mm.x(), 400, 1e-9);
	EXPECT_NEAR(g.p_mm.z(), 330, 1e-9);
	EXPECT_NEAR(g.yaw_deg, 0, 0);
	const auto turned = box({400, 0, 0}, 40, 100, 60, 300);
	EXPECT_NEAR(topGrasp(turned.lines, turned.conics).yaw_deg, 90, 0);
}

TEST(ArmGraspFeasibility, ReachableNarrowObjectOnAClearTableIsFeasible)
{
	const auto wf = box({400, 0, 0}, 100, 40, 60, 300);
	const auto pts = sampleWireFrame(wf, Eigen::Isometry3d::Identity(), 2);
	const GripperPose g = topGrasp(wf.lines, wf.conics);
	const GraspCheck c =
	    checkGrasp(topAt(g), pts, {}, 300, AnalyticIk(), GraspFeasibilityOptions());
	EXPECT_TRUE(c.feasible()) << (c.reasons.empty() ? "" : c.reasons[0]);
	EXPECT_NEAR(c.width_mm, 40, 1e-9);
	EXPECT_FALSE(c.solutions.empty());
	EXPECT_NEAR(c.table_clearance_mm, 30 - 20, 1e-9);  // centroid 30 mm up, fingertips 20 below it
}

TEST(ArmGraspFeasibility, EachFailedCheckIsNamed)
{
	const GraspFeasibilityOptions o;
	const AnalyticIk ik;
	const auto wide = box({400, 0, 0}, 120, 120, 60, 300);
	const auto wide_pts = sampleWireFrame(wide, Eigen::Isometry3d::Identity(), 2);
	GraspCheck c = checkGrasp(topAt(topGrasp(wide.lines, {})), wide_pts, {}, 300, ik, o);
	EXPECT_THAT(c.reasons.at(0), HasSubstr("too wide"));

	const auto far = box({900, 0, 0}, 100, 40, 60, 300);  // beyond the ≈ 500 mm reach
	c = checkGrasp(topAt(topGrasp(far.lines, {})), sampleWireFrame(far, kIdentity, 2), {}, 300, ik,
	               o);
	EXPECT_THAT(c.reasons.at(0), HasSubstr("out of reach: wrist radius"));

	const auto flat = box({400, 0, 0}, 100, 40, 10, 300);  // 5 mm tall: fingertips hit the table
	c = checkGrasp(topAt(topGrasp(flat.lines, {})), sampleWireFrame(flat, kIdentity, 2), {}, 300,
	               ik, o);
	ASSERT_FALSE(c.feasible());
	EXPECT_THAT(c.reasons.back(), HasSubstr("table"));

	const auto obj = box({400, 0, 0}, 100, 40, 60, 300);
	const auto next = box({400, 70, 0}, 30, 30, 60, 300);  // a neighbour 70 mm to the side
	c = checkGrasp(topAt(topGrasp(obj.lines, {})), sampleWireFrame(obj, kIdentity, 2),
	               sampleWireFrame(next, kIdentity, 2), 300, ik, o);
	ASSERT_FALSE(c.feasible());
	EXPECT_THAT(c.reasons.back(), HasSubstr("neighbouring-object points"));
	EXPECT_GT(c.neighbour_points_in_path, 0);

	// Nothing between the fingers: a grasp point beside the object.
	GripperPose beside = topGrasp(obj.lines, {});
	beside.p_mm.x() += 80;  // fingers 30 mm past the box end
	c = checkGrasp(topAt(beside), sampleWireFrame(obj, kIdentity, 2), {}, 300, ik, o);
	EXPECT_THAT(c.reasons.at(0), HasSubstr("no object point between the fingers"));
}

TEST(ArmGraspFeasibility, OptionsFileEqualsDefaults)
{
	const auto [shipped, defaults] =
	    test::shippedAndDefaultDump<GraspFeasibilityOptions>("arm_grasp");
	EXPECT_EQ(shipped, defaults);
}
