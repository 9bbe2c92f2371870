// The table top estimated from the stereo scene alone (recog::estimateTablePlane) against the
// world's: rendered lab views of cluttered tables, the robot's prior off by 40 mm.
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/recog/plane/TablePlaneEstimate.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <cstdio>

using namespace mrolr;

namespace
{
eval::EvaluationOptions shippedOptions()
{
	eval::EvaluationOptions o;
	o.loadFromConfigFile(
	    mrpt::config::CConfigFile(util::requireProjectFile("config/recognition.ini")), "evaluation");
	return o;
}

/** Height difference (mm) of two planes at @p p_L, and the angle (deg) between their normals. */
std::pair<double, double> planeError(const recog::SupportPlane& a, const recog::SupportPlane& b,
                                     const Eigen::Vector3d& p_L)
{
	const double angle = std::acos(std::min(1.0, a.n_S.dot(b.n_S))) * 180.0 / M_PI;
	return {std::abs(a.height_mm(p_L) - b.height_mm(p_L)), angle};
}
}  // namespace

TEST(TablePlaneEstimate, WithinOneDegreeAndThreeMillimetresOnTheLabsViews)
{
	auto gen = eval::makeSceneGenerator(shippedOptions());
	const int scenes = 30;
	int found = 0;
	double worst_mm = 0, worst_deg = 0;
	for (int k = 1; k <= scenes; ++k)
	{
		const eval::EvalScene s = gen->make(k);
		const double true_h = -s.plane_L.d_mm;  // the top's height along up, L's origin at 0
		for (double prior_error_mm : {-40.0, 40.0})
		{
			const auto e = recog::estimateTablePlane(s.scene, s.up_L, {true_h + prior_error_mm});
			ASSERT_TRUE(e.found) << "scene " << k << ": " << e.reason;
			++found;
			// compared under the objects: the mean of their true origins (on the top)
			Eigen::Vector3d centre = Eigen::Vector3d::Zero();
			for (const auto& o : s.objects) centre += o.T_OinL.translation();
			centre /= double(std::max<size_t>(1, s.objects.size()));
			const auto [mm, deg] = planeError(e.plane, s.plane_L, centre);
			EXPECT_LT(mm, 3.0) << "scene " << k << " prior " << prior_error_mm;
			EXPECT_LT(deg, 1.0) << "scene " << k << " prior " << prior_error_mm;
			worst_mm = std::max(worst_mm, mm), worst_deg = std::max(worst_deg, deg);
		}
	}
	std::printf("table plane over %d estimates: worst %.2f mm, %.2f deg\n", found, worst_mm,
	            worst_deg);
}

TEST(TablePlaneEstimate, NothingNearTheExpectedHeightIsNotFoundAndSaysWhy)
{
	model::WireFrame empty;
	model::Line3 l;
	l.p1 = {0, -500, 800}, l.p2 = {300, -500, 800};
	empty.lines.push_back(l);
	const auto e = recog::estimateTablePlane(empty, Eigen::Vector3d::UnitY(), {-200});
	EXPECT_FALSE(e.found);
	EXPECT_NE(e.reason.find("expected table height"), std::string::npos);
	const auto near = recog::estimateTablePlane(empty, Eigen::Vector3d::UnitY(), {-480});
	ASSERT_TRUE(near.found);
	EXPECT_NEAR(near.plane.height_mm({100, -500, 900}), 0, 1e-9);
}
