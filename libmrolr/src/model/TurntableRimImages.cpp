#include <mrolr/model/ArcOfBins.h>
#include <mrolr/model/TurntableRimImages.h>

#include <array>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <tuple>

namespace mrolr::model
{
namespace
{
constexpr int kBins = 36;  // 10° pieces
constexpr int kSamplesPerBin = 5;

double wrap(double t)
{
	t = std::fmod(t, 2 * M_PI);
	return t < 0 ? t + 2 * M_PI : t;
}

/** Which 10° bins (from angle 0 of the conic's parameter) have their middle on the arc t1..t2. */
std::array<bool, kBins> arcBins(const Conic3& c)
{
	std::array<bool, kBins> bins{};
	const double bin = 2 * M_PI / kBins;
	for (int k = 0; k < kBins; ++k) bins[k] = wrap((k + 0.5) * bin - c.t1) <= c.t2 - c.t1;
	return bins;
}

std::vector<FeatureSample> binSamples(const Conic3& c, int k)
{
	std::vector<FeatureSample> s;
	const double bin = 2 * M_PI / kBins;
	for (int i = 0; i < kSamplesPerBin; ++i)
	{
		FeatureSample q;
		q.p = c.pointAt((k + (i + 0.5) / kSamplesPerBin) * bin);
		s.push_back(q);
	}
	return s;
}

bool facedBy(const Conic3& c, const std::vector<FeatureSample>& s, const ViewEdges& v,
             double min_cos)
{
	const Eigen::Vector3d cam_O = v.T_OinL.inverse().translation();
	for (const auto& q : s)
	{
		const Eigen::Vector3d radial = (q.p - c.centre).normalized();
		if (radial.dot((cam_O - q.p).normalized()) < min_cos) return false;
	}
	return true;
}

bool shownByImages(const Conic3& c, int k, const std::vector<ViewEdges>& edges,
                   const RimImageOptions& o)
{
	const auto s = binSamples(c, k);
	for (const auto& v : edges)
		if (facedBy(c, s, v, o.min_facing_cos) &&
		    imageEdgeShare(s, v, o.min_gradient) >= o.min_fraction)
			return true;
	return false;
}

/** The circle minus its largest run of uncovered bins (as the rims' arcOf). */
void setArc(Conic3& c, const std::array<bool, kBins>& bins)
{
	std::tie(c.t1, c.t2) = arcOfBins(bins, 0.0);
}
}  // namespace

double meanFacingGradient(const Conic3& c, const std::vector<ViewEdges>& edges,
                          const RimImageOptions& o)
{
	double sum = 0;
	size_t n = 0;
	for (int k = 0; k < kBins; ++k)
	{
		const auto s = binSamples(c, k);
		for (const auto& v : edges)
			if (facedBy(c, s, v, o.min_facing_cos))
				for (const auto& q : s)
				{
					const Eigen::Vector3d p = v.T_OinL * q.p;
					if (p.z() <= 1) continue;
					std::vector<cv::Point2d> px;
					cv::projectPoints(std::vector<cv::Point3d>{{-p.x(), -p.y(), p.z()}},
					                  cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), v.K, v.D, px);
					const cv::Point i(static_cast<int>(std::lround(px[0].x)),
					                  static_cast<int>(std::lround(px[0].y)));
					if (i.x < 0 || i.y < 0 || i.x >= v.gradient.cols || i.y >= v.gradient.rows)
						continue;
					sum += v.gradient.at<float>(i), ++n;
				}
	}
	return n ? sum / static_cast<double>(n) : 0.0;
}

int arcFromImages(Conic3& c, const std::vector<ViewEdges>& edges, const RimImageOptions& o)
{
	std::array<bool, kBins> bins{};
	int n = 0;
	for (int k = 0; k < kBins; ++k)
		if (shownByImages(c, k, edges, o)) bins[k] = true, ++n;
	if (n == 0)
		c.t1 = c.t2 = 0;
	else
		setArc(c, bins);
	return n;
}

int completeRimsFromImages(std::vector<Conic3>& rims, const std::vector<ViewEdges>& edges,
                           const RimImageOptions& o)
{
	if (o.min_gradient <= 0 || edges.empty()) return 0;
	int added = 0;
	for (auto& c : rims)
	{
		const bool horizontal =
		    std::abs(c.normal.normalized().z()) >= std::cos(o.max_tilt_deg * M_PI / 180);
		if (!horizontal || std::abs(c.a - c.b) > 1e-6 * c.a || c.t2 - c.t1 >= 2 * M_PI - 1e-9)
			continue;
		auto bins = arcBins(c);
		int n = 0;
		for (int k = 0; k < kBins; ++k)
			if (!bins[k] && shownByImages(c, k, edges, o)) bins[k] = true, ++n;
		if (n == 0) continue;
		const Conic3 before = c;
		setArc(c, bins);
		if (c.t2 - c.t1 > before.t2 - before.t1)
			added += n;
		else
			c = before;  // the largest gap did not shrink: keep the arc found in 3D
	}
	return added;
}

}  // namespace mrolr::model
