// RunProjection, the image verification's arithmetic a run of samples at a time: the same bits as
// one sample at a time through Eigen (the pose) and cv::projectPoints (the lens), so that
// vectorising it leaves every image score as it was.
#include <mrolr/recog/images/ProjectedRun.h>

#include <opencv2/calib3d.hpp>

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace mrolr::recog;

namespace
{
cv::Point2d projectPoints(const Eigen::Vector3d& p_C, const cv::Matx33d& K,
                          const cv::Vec<double, 5>& D)
{
	std::vector<cv::Point3d> in{{p_C.x(), p_C.y(), p_C.z()}};
	std::vector<cv::Point2d> out;
	cv::projectPoints(in, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D, out);
	return out.front();
}

std::vector<EdgeSample> randomSamples(std::mt19937& rng, int n)
{
	std::uniform_real_distribution<double> pos(-120, 120), dir(-1, 1);
	std::vector<EdgeSample> s;
	for (int k = 0; k < n; ++k)
		s.push_back({Eigen::Vector3d(pos(rng), pos(rng), pos(rng)),
		             Eigen::Vector3d(dir(rng), dir(rng), dir(rng)).normalized(), k});
	return s;
}
}  // namespace

// Runs of every length up to kMax, at poses that put some samples out of view (behind the camera
// or beyond 45 degrees), with a lens of strong distortion and with one of none (RunProjection
// leaves the polynomial out then).
TEST(ProjectedRun, GivesTheSameBitsAsEigenAndProjectPointsOneSampleAtATime)
{
	std::mt19937 rng(7);
	const cv::Matx33d K(812.5, 0, 321.25, 0, 809.75, 238.5, 0, 0, 1);
	std::uniform_real_distribution<double> angle(-M_PI, M_PI), depth(-200, 900);
	int in_view = 0, out_of_view = 0;
	for (const cv::Vec<double, 5>& D :
	     {cv::Vec<double, 5>(-0.31, 0.12, 0.0013, -0.0021, -0.02), cv::Vec<double, 5>::all(0)})
		for (int pose = 0; pose < 40; ++pose)
		{
			const Eigen::Isometry3d T_OinC =
			    Eigen::Translation3d(0.3 * depth(rng), 0.3 * depth(rng), depth(rng)) *
			    Eigen::AngleAxisd(angle(rng), Eigen::Vector3d(1, 2, 3).normalized());
			const size_t n = 1 + static_cast<size_t>(pose) % ProjectedRun::kMax;
			const auto samples = randomSamples(rng, static_cast<int>(n));
			ProjectedRun run;
			RunProjection(T_OinC, K, D).project(samples.data(), n, run);
			ASSERT_EQ(run.n, n);
			for (size_t k = 0; k < n; ++k)
			{
				const Eigen::Vector3d p = T_OinC * samples[k].p_O;
				const Eigen::Vector3d q = p + T_OinC.linear() * samples[k].t_O;
				EXPECT_EQ(run.x[k], p.x());
				EXPECT_EQ(run.y[k], p.y());
				EXPECT_EQ(run.z[k], p.z());
				const bool seen = inView(p.x(), p.y(), p.z()) && inView(q.x(), q.y(), q.z());
				EXPECT_EQ(run.in_view[k] != 0, seen);
				(seen ? in_view : out_of_view) += 1;
				if (!seen) continue;  // projectPoints folds such points back in; they are not used
				const cv::Point2d px = projectPoints(p, K, D), qx = projectPoints(q, K, D);
				EXPECT_EQ(run.u[k], px.x);
				EXPECT_EQ(run.v[k], px.y);
				EXPECT_EQ(run.tu[k], qx.x - px.x);
				EXPECT_EQ(run.tv[k], qx.y - px.y);
			}
		}
	EXPECT_GT(in_view, 100);
	EXPECT_GT(out_of_view, 40);
}

TEST(ProjectedRun, RefusesARunLongerThanItsArrays)
{
	const std::vector<EdgeSample> samples(ProjectedRun::kMax + 1);
	ProjectedRun run;
	EXPECT_THROW(
	    RunProjection(Eigen::Isometry3d::Identity(), cv::Matx33d::eye(), cv::Vec<double, 5>())
	        .project(samples.data(), samples.size(), run),
	    std::invalid_argument);
}

// A model's samples transposed once (sampleBlocksOf, what SightedSamples keeps): blocks of kMax in
// order, the last one shorter, each projected to the bits of the same samples projected directly.
TEST(ProjectedRun, SampleBlocksHoldTheSamplesInOrderAndProjectTheSame)
{
	std::mt19937 rng(11);
	const cv::Matx33d K(812.5, 0, 321.25, 0, 809.75, 238.5, 0, 0, 1);
	const cv::Vec<double, 5> D(-0.31, 0.12, 0.0013, -0.0021, -0.02);
	const Eigen::Isometry3d T_OinC =
	    Eigen::Translation3d(5, -8, 600) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY());
	for (const int n : {0, 1, 16, 17, 40})
	{
		const auto samples = randomSamples(rng, n);
		const auto blocks = sampleBlocksOf(samples);
		ASSERT_EQ(blocks.size(), (samples.size() + ProjectedRun::kMax - 1) / ProjectedRun::kMax);
		for (size_t b = 0; b < blocks.size(); ++b)
		{
			const size_t first = b * ProjectedRun::kMax;
			ASSERT_EQ(blocks[b].n, std::min(ProjectedRun::kMax, samples.size() - first));
			ProjectedRun from_block, direct;
			RunProjection(T_OinC, K, D).project(blocks[b], from_block);
			RunProjection(T_OinC, K, D).project(samples.data() + first, blocks[b].n, direct);
			for (size_t k = 0; k < blocks[b].n; ++k)
			{
				EXPECT_EQ(blocks[b].p[2][k], samples[first + k].p_O.z());
				EXPECT_EQ(blocks[b].d[0][k], samples[first + k].t_O.x());
				EXPECT_EQ(from_block.u[k], direct.u[k]);
				EXPECT_EQ(from_block.tv[k], direct.tv[k]);
				EXPECT_EQ(from_block.z[k], direct.z[k]);
			}
		}
	}
}
