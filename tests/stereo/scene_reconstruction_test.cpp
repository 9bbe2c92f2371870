#include "SyntheticStereo.h"

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/EdgeStrings.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/Rectifier.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
/** Rectified left pixel and disparity of p_L (thesis axes, mm), inverse of pointInLeftCamera. */
StereoEdgel project(const Rectifier& r, const Eigen::Vector3d& p_L)
{
	const cv::Vec3d p_cv(-p_L.x(), -p_L.y(), p_L.z());
	const cv::Vec3d q = r.R_RectFromL() * p_cv;
	const cv::Point2d c = r.principalPoint_px();
	return {{r.focal_px() * q[0] / q[2] + c.x, r.focal_px() * q[1] / q[2] + c.y},
	        r.disparityAtDepth(q[2]),
	        p_L};
}

std::vector<StereoEdgel> alongCurve(const Rectifier& r,
                                    const std::function<Eigen::Vector3d(double)>& curve, int n,
                                    double noise_px)
{
	std::mt19937 rng(7);
	std::normal_distribution<double> g(0, noise_px);
	std::vector<StereoEdgel> e;
	for (int i = 0; i < n; ++i)
	{
		StereoEdgel x = project(r, curve(static_cast<double>(i) / (n - 1)));
		x.d_px += g(rng);
		x.p_L_mm = r.pointInLeftCamera(x.xy_px.x, x.xy_px.y, x.d_px);
		e.push_back(x);
	}
	return e;
}

/** A vertical step edge at column x_edge (px) rendered with 8x supersampling. */
cv::Mat stepImage(double x_edge)
{
	cv::Mat big(480 * 8, 640 * 8, CV_8U, cv::Scalar(60));
	big(cv::Rect(static_cast<int>(std::lround((x_edge + 0.5) * 8)), 0,
	             640 * 8 - static_cast<int>(std::lround((x_edge + 0.5) * 8)), 480 * 8)) = 190;
	cv::Mat img;
	cv::resize(big, img, {640, 480}, 0, 0, cv::INTER_AREA);
	return img;
}
}  // namespace

TEST(Rectifier, PointInLeftCameraInvertsTheRectifiedProjection)
{
	const Rectifier r(testRig(0.05));
	EXPECT_NEAR(r.baseline_mm(), 120, 1e-6);
	for (const Eigen::Vector3d& p :
	     {Eigen::Vector3d(100, -50, 900), Eigen::Vector3d(-300, 200, 2000)})
	{
		const StereoEdgel e = project(r, p);
		EXPECT_LT((r.pointInLeftCamera(e.xy_px.x, e.xy_px.y, e.d_px) - p).norm(), 1e-9);
	}
	cv::Mat a, b;
	EXPECT_THROW(r.rectify(cv::Mat(10, 10, CV_8U), cv::Mat(10, 10, CV_8U), a, b),
	             std::runtime_error);
}

TEST(EdgeStrings, SubPixelPositionOfAStepEdge)
{
	for (double x0 : {200.0, 200.25, 311.6})
	{
		const auto strings = detectEdgeStrings(stepImage(x0), EdgeOptions());
		ASSERT_FALSE(strings.empty());
		double sum = 0;
		int n = 0;
		for (const auto& s : strings)
			for (const auto& e : s)
				if (e.p.y > 20 && e.p.y < 460) sum += e.p.x, ++n;
		ASSERT_GT(n, 300);
		EXPECT_NEAR(sum / n, x0, 0.1) << x0;
	}
	EXPECT_THROW(detectEdgeStrings(cv::Mat(), EdgeOptions()), std::invalid_argument);
}

TEST(EdgeMatcher, FrontoParallelCardGivesItsDisparity)
{
	const auto rig = testRig(0.0);
	const Eigen::Matrix3d A = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	cv::Mat L, R;
	renderPair({rectangle({0, 0, 1000}, A.col(0), A.col(1), 200, 150, 200)}, rig, L, R);
	const Rectifier rect(rig);
	cv::Mat lr, rr;
	rect.rectify(L, R, lr, rr);
	const auto ls = detectEdgeStrings(lr, EdgeOptions()), rs = detectEdgeStrings(rr, EdgeOptions());
	const auto m = matchEdgeStrings(ls, rs, 20, 200, MatchOptions());
	ASSERT_GT(m.size(), 200u);
	const double d_true = rect.disparityAtDepth(1000);
	int good = 0;
	for (const auto& x : m) good += std::abs(x.disparity_px - d_true) < 0.3;
	EXPECT_GT(good, 0.95 * m.size());
}

TEST(Fit3, LineFromNoisyDisparitiesKeepsItsEndpoints)
{
	const Rectifier r(testRig());
	const Eigen::Vector3d a(-80, 40, 900), b(60, -70, 1050);
	const auto e = alongCurve(
	    r, [&](double s) { return Eigen::Vector3d(a + s * (b - a)); }, 120, 0.1);
	const auto l = fitLine3(e, r, FitOptions());
	ASSERT_TRUE(l.has_value());
	EXPECT_LT((l->p1 - a).norm(), 2.0);
	EXPECT_LT((l->p2 - b).norm(), 2.0);
	EXPECT_GT(l->rms_mm, 0.0);
}

TEST(Fit3, CircleArcGivesCentreRadiusAndNormal)
{
	const Rectifier r(testRig());
	const Eigen::Vector3d c(20, 60, 950), u(1, 0, 0), v = Eigen::Vector3d(0, 0.6, -0.8),
	                                                  n = u.cross(v);
	const auto e = alongCurve(
	    r,
	    [&](double s)
	    {
		    const double t = -2.0 + 3.5 * s;
		    return Eigen::Vector3d(c + 50 * (std::cos(t) * u + std::sin(t) * v));
	    },
	    200, 0.1);
	const auto k = fitConic3(e, r, FitOptions());
	ASSERT_TRUE(k.has_value());
	EXPECT_LT((k->centre - c).norm(), 1.5);
	EXPECT_NEAR(k->a, 50, 1.0);
	EXPECT_NEAR(k->b, 50, 1.0);
	EXPECT_GT(std::abs(k->normal.dot(n)), std::cos(3 * M_PI / 180));
	EXPECT_NEAR(k->t2 - k->t1, 3.5, 0.1);
	EXPECT_FALSE(fitLine3(e, r, FitOptions()).has_value());
}

TEST(Fit3, CornerStringSplitsIntoTwoLines)
{
	const Rectifier r(testRig());
	const Eigen::Vector3d a(-80, 40, 900), b(0, -60, 950), c(90, 30, 1000);
	const auto e = alongCurve(
	    r,
	    [&](double s)
	    { return Eigen::Vector3d(s < 0.5 ? a + 2 * s * (b - a) : b + (2 * s - 1) * (c - b)); },
	    201, 0.05);
	std::vector<LineFit3> lines;
	std::vector<ConicFit3> conics;
	segmentString(e, r, FitOptions(), lines, conics);
	ASSERT_EQ(lines.size(), 2u);
	EXPECT_TRUE(conics.empty());
	EXPECT_LT((lines[0].p2 - b).norm(), 3.0);
	EXPECT_LT((lines[1].p1 - b).norm(), 3.0);
}
