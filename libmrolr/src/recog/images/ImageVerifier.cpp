#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/images/ImageVerifier.h>

#include "EdgeImageVisit.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrolr::recog
{
namespace
{
cv::Mat greyOf(const cv::Mat& img, const char* which)
{
	if (img.empty()) throw std::invalid_argument(std::string("image verification: empty ") + which);
	if (img.depth() != CV_8U)
		throw std::invalid_argument(std::string("image verification: ") + which +
		                            " image is not 8-bit");
	if (img.channels() == 1) return img;
	cv::Mat g;
	cv::cvtColor(img, g, img.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
	return g;
}

/** Pose in L of the OpenCV camera whose points are p_cv = R p_Lcv + t (L's OpenCV twin has x, y
 * negated). */
Eigen::Isometry3d cameraInL(const cv::Matx33d& R_CfromLcv, const cv::Vec3d& t_LcvInC_mm)
{
	Eigen::Isometry3d T_LcvInC = Eigen::Isometry3d::Identity();
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j) T_LcvInC.linear()(i, j) = R_CfromLcv(i, j);
		T_LcvInC.translation()[i] = t_LcvInC_mm[i];
	}
	Eigen::Isometry3d T_LcvInL = Eigen::Isometry3d::Identity();
	T_LcvInL.linear() = Eigen::Vector3d(-1, -1, 1).asDiagonal();
	return T_LcvInL * T_LcvInC.inverse();
}

/** The sub-pixel position of the edge through the Canny pixel (@p x, @p y): the peak of the
 * gradient magnitude along its direction, a parabola through the pixel and its two neighbours
 * that way (Devernay 1995). A step between two pixels has its edge half-way; the pixel Canny
 * keeps is on one side of it, always the same side for one direction. */
cv::Point2f subpixelEdge(const cv::Mat& gx, const cv::Mat& gy, int x, int y)
{
	const auto magnitude = [&](int u, int v)
	{ return std::hypot(double(gx.at<short>(v, u)), double(gy.at<short>(v, u))); };
	const double m0 = magnitude(x, y);
	const cv::Point2f at(static_cast<float>(x), static_cast<float>(y));
	if (m0 <= 0) return at;
	const int sx = static_cast<int>(std::lround(gx.at<short>(y, x) / m0));
	const int sy = static_cast<int>(std::lround(gy.at<short>(y, x) / m0));
	if (x - sx < 0 || y - sy < 0 || x + sx >= gx.cols || y + sy >= gx.rows) return at;
	const double before = magnitude(x - sx, y - sy), after = magnitude(x + sx, y + sy);
	const double curvature = before - 2 * m0 + after;
	if (curvature >= 0) return at;  // not a peak
	const double t = std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5);
	return at + cv::Point2f(static_cast<float>(t * sx), static_cast<float>(t * sy));
}
}  // namespace

Eigen::Vector3d upAxisPoint(const std::vector<Feature>& features)
{
	Eigen::Vector3d sum = Eigen::Vector3d::Zero(), all = Eigen::Vector3d::Zero();
	int n = 0;
	for (const auto& f : features)
	{
		all += f.m;
		if (f.isLine() || std::abs(f.u.z()) < std::cos(25 * M_PI / 180)) continue;
		sum += f.m, ++n;
	}
	if (n) return sum / n;
	return features.empty() ? all : Eigen::Vector3d(all / static_cast<double>(features.size()));
}

std::vector<Eigen::Vector3d> upAxisPoints(const std::vector<Feature>& features)
{
	std::vector<Eigen::Vector3d> out = {upAxisPoint(features)};
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	double length = 0;
	for (const auto& f : features) sum += f.len_mm * f.m, length += f.len_mm;
	if (length <= 0) return out;
	const Eigen::Vector3d c = sum / length;
	if ((c - out.front()).head<2>().norm() > 2.0) out.push_back(c);
	return out;
}

std::vector<EdgeSample> edgeSamplesOf(const std::vector<Feature>& features, double spacing_mm)
{
	std::vector<EdgeSample> out;
	for (size_t k = 0; k < features.size(); ++k)
	{
		const Feature& f = features[k];
		const int n = std::max(2, static_cast<int>(std::ceil(f.len_mm / spacing_mm)));
		const auto pts = samplesOf(f, n);
		for (const auto& p : pts)
		{
			const Eigen::Vector3d t = f.isLine() ? f.u : f.u.cross(p - f.m).normalized();
			out.push_back({p, t, static_cast<int>(k)});
		}
	}
	return out;
}

std::vector<EdgeSample> edgeSamplesOf(const model::WireFrame& wf, double spacing_mm)
{
	std::vector<EdgeSample> out;
	for (const auto& s : model::sampleWireFrame(wf, spacing_mm))
		out.push_back({s.p, s.tangent, s.feature});
	return out;
}

EdgeImage::EdgeImage(const cv::Mat& grey, const cv::Matx33d& K, const cv::Vec<double, 5>& D,
                     const Eigen::Isometry3d& T_CcvInL, const ImageVerificationOptions& o)
    : K_(K),
      D_(D),
      T_CcvInL_(T_CcvInL),
      T_LinCcv_(T_CcvInL.inverse()),
      dist_px_(o.edge_distance_px),
      sin_tol_(std::sin(o.orientation_tol_deg * M_PI / 180)),
      limbs_(o.limbs),
      revolution_visibility_(o.revolution_visibility),
      limb_spacing_mm_(o.sample_spacing_mm)
{
	cv::Mat blurred = grey, gx, gy;
	if (o.blur_sigma_px > 0) cv::GaussianBlur(grey, blurred, cv::Size(0, 0), o.blur_sigma_px);
	cv::Sobel(blurred, gx, CV_16S, 1, 0, 3);
	cv::Sobel(blurred, gy, CV_16S, 0, 1, 3);
	cv::Canny(gx, gy, edges_, o.canny_low, o.canny_high, true);
	cv::distanceTransform(edges_ == 0, dist_, labels_, cv::DIST_L2, cv::DIST_MASK_5,
	                      cv::DIST_LABEL_PIXEL);
	if (cv::countNonZero(edges_) == 0) dist_.setTo(1e9);
	reach_ = reachOf(dist_, dist_px_, o.truncate_px), reach_truncate_px_ = o.truncate_px;
	for (int y = 0; y < edges_.rows; ++y)
		for (int x = 0; x < edges_.cols; ++x)
		{
			if (!edges_.at<uchar>(y, x)) continue;
			const size_t label = static_cast<size_t>(labels_.at<int>(y, x));
			if (label >= normal_.size())
				normal_.resize(label + 1, cv::Point2f(0, 0)), edge_px_.resize(label + 1);
			edge_px_[label] = subpixelEdge(gx, gy, x, y);
			const cv::Point2f g(gx.at<short>(y, x), gy.at<short>(y, x));
			const double n = std::hypot(g.x, g.y);
			normal_[label] = n > 0 ? g / static_cast<float>(n) : cv::Point2f(0, 0);
		}
	const float none = std::numeric_limits<float>::quiet_NaN();
	nearest_normal_.create(edges_.size(), CV_32FC2);
	for (int y = 0; y < edges_.rows; ++y)
	{
		const int* label = labels_.ptr<int>(y);
		auto* out = nearest_normal_.ptr<cv::Vec2f>(y);
		for (int x = 0; x < edges_.cols; ++x)
		{
			const auto k = static_cast<size_t>(label[x]);
			out[x] =
			    k < normal_.size() ? cv::Vec2f(normal_[k].x, normal_[k].y) : cv::Vec2f(none, none);
		}
	}
}

cv::Mat reachOf(const cv::Mat& dist, double dist_px, double truncate_px)
{
	// in double, as count() compares (cv::compare would round the bounds to float)
	cv::Mat reach(dist.size(), CV_8U);
	for (int y = 0; y < dist.rows; ++y)
	{
		const float* d = dist.ptr<float>(y);
		auto* out = reach.ptr<std::uint8_t>(y);
		for (int x = 0; x < dist.cols; ++x)
			out[x] = d[x] <= dist_px                                   ? kClose
			         : truncate_px > 0 && d[x] < truncate_px + kFar_px ? kNear
			                                                           : kBeyond;
	}
	return reach;
}

SightedSamples::SightedSamples(std::vector<EdgeSample> samples, const SelfOcclusion* occlusion)
    : samples_O(std::move(samples)), occ(occlusion), blocks(sampleBlocksOf(samples_O))
{
	if (!occ) return;
	sights.reserve(samples_O.size());
	for (const auto& s : samples_O) sights.push_back(occ->pointSight(s.p_O));
}

std::vector<EdgeSample> EdgeImage::limbsSeen(const SightedSamples& ss,
                                             const Eigen::Isometry3d& T_OinL) const
{
	std::vector<EdgeSample> limbs;
	limbsSeen(ss, T_OinL, limbs);
	return limbs;
}

void EdgeImage::limbsSeen(const SightedSamples& ss, const Eigen::Isometry3d& T_OinL,
                          std::vector<EdgeSample>& limbs) const
{
	limbs.clear();
	if (!limbs_ || !ss.occ) return;
	const Eigen::Vector3d c_O = T_OinL.inverse() * centre_L();
	for (const auto& body : ss.occ->revolutionBodies())
		appendLimbSamples(body, c_O, limb_spacing_mm_, limbs);
}

ImageCount EdgeImage::count(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
                            double truncate_px) const
{
	static thread_local std::vector<EdgeSample> limbs;  // kept per thread: a score per pose
	limbsSeen(s, T_OinL, limbs);
	return *count(s, T_OinL, limbs, truncate_px, nullptr);
}

std::optional<ImageCount> EdgeImage::count(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
                                           const std::vector<EdgeSample>& limbs, double truncate_px,
                                           ScoreCap* cap, std::vector<AlignedSample>* aligned) const
{
	// two instances, so that the counts that keep nothing (the sweep's) pay nothing for it
	if (!aligned)
		return countKeeping(s, T_OinL, limbs, truncate_px, cap,
		                    [](const cv::Point2d&, const Eigen::Vector3d&) {});
	aligned->clear();
	return countKeeping(s, T_OinL, limbs, truncate_px, cap,
	                    [aligned](const cv::Point2d& px, const Eigen::Vector3d& p_C) {
		                    aligned->push_back({px, p_C});
	                    });
}

template <class Keep>
std::optional<ImageCount> EdgeImage::countKeeping(const SightedSamples& s,
                                                  const Eigen::Isometry3d& T_OinL,
                                                  const std::vector<EdgeSample>& limbs,
                                                  double truncate_px, ScoreCap* cap,
                                                  Keep keep) const
{
	ImageCount c;
	bool exceeded = false;
	// the cap is asked every 4th sample and once at the end: once exceeded it stays so (its
	// bounds only tighten as samples are counted), so the answer is the same, for 3 tests in 4
	// fewer and at most 3 samples more
	const auto stop = [&]
	{
		if (!cap) return false;
		--cap->unvisited;
		if (cap->unvisited % 4 == 0) exceeded = cap->exceeded();
		return exceeded;
	};
	forEachInView<false>(
	    s, T_OinL, limbs,
	    [&](const cv::Point2d& px, const cv::Point2d& tangent, bool, bool,
	        const Eigen::Vector3d& p_C)
	    {
		    const Pixel at = pixelOf(px);
		    if (occludedAt(at, p_C.z()))
		    {
			    ++c.occluded;
			    return;
		    }
		    ++c.considered;
		    // the nearest edge's direction (a look-up that misses the cache) matters only where
		    // the sample may be supported or cost less than the cap
		    const std::uint8_t reach = reachAt(at, truncate_px);
		    const bool on_edge = reach != kBeyond && oriented(at, tangent);
		    if (on_edge) keep(px, p_C);
		    const int supported = on_edge && reach == kClose ? 1 : 0;
		    c.supported += supported;
		    if (cap) ++cap->considered, cap->supported += supported;
		    if (truncate_px <= 0) return;
		    const double d = on_edge ? std::min(truncate_px, distanceAt(px)) : truncate_px;
		    c.cost_px2 += d * d;
		    if (cap) cap->sum_px2 += d * d;
	    },
	    stop, &c.outside);
	if (cap && (exceeded || cap->exceeded())) return std::nullopt;
	return c;
}

std::vector<EdgeImage::Judged> EdgeImage::judge(const std::vector<EdgeSample>& s_O,
                                                const Eigen::Isometry3d& T_OinL,
                                                const SelfOcclusion* occ) const
{
	std::vector<Judged> out;
	const SightedSamples sighted(s_O, occ);
	forEachInView<true>(
	    sighted, T_OinL, limbsSeen(sighted, T_OinL),
	    [&](const cv::Point2d& px, const cv::Point2d& tangent, bool hidden, bool limb,
	        const Eigen::Vector3d& p_C)
	    {
		    hidden = hidden || occludedAt(pixelOf(px), p_C.z());
		    out.push_back({px, limb, hidden, !hidden && supports(px, tangent)});
	    },
	    [] { return false; }, nullptr);
	return out;
}

ImageVerifier::ImageVerifier(const cv::Mat& left, const cv::Mat& right,
                             const stereo::StereoCalibration& calib,
                             const ImageVerificationOptions& o)
    : opts_(o)
{
	const cv::Mat l = greyOf(left, "left"), r = greyOf(right, "right");
	if (l.size() != calib.image_size || r.size() != calib.image_size)
		throw std::invalid_argument(
		    "image verification: images are " + std::to_string(l.cols) + "x" +
		    std::to_string(l.rows) + " and " + std::to_string(r.cols) + "x" +
		    std::to_string(r.rows) + " px, the calibration's " +
		    std::to_string(calib.image_size.width) + "x" + std::to_string(calib.image_size.height));
	images_.emplace_back(l, calib.K_left, calib.D_left,
	                     cameraInL(cv::Matx33d::eye(), cv::Vec3d(0, 0, 0)), o);
	images_.emplace_back(r, calib.K_right, calib.D_right,
	                     cameraInL(calib.R_RfromL, calib.t_LinR_mm), o);
}

ImageScore ImageVerifier::score(const std::vector<EdgeSample>& samples_O,
                                const Eigen::Isometry3d& T_OinL, const SelfOcclusion* occ) const
{
	return score(SightedSamples(samples_O, occ), T_OinL);
}

ImageScore ImageVerifier::score(const SightedSamples& samples, const Eigen::Isometry3d& T_OinL,
                                bool with_cost) const
{
	// without the cost's cap, count() looks up the nearest edge's direction only for the samples
	// that may be supported, and no distance at all
	std::array<ImageCount, 2> counts;
	for (size_t i = 0; i < images_.size(); ++i)
		counts[i] = images_[i].count(samples, T_OinL, with_cost ? opts_.truncate_px : 0);
	return combined(counts);
}

ImageScore ImageVerifier::combined(const std::array<ImageCount, 2>& counts) const
{
	ImageScore s;
	for (size_t i = 0; i < counts.size(); ++i)
	{
		const ImageCount& c = counts[i];
		s.per_image[i] = c.considered ? static_cast<double>(c.supported) / c.considered : 0.0;
		s.considered += c.considered, s.supported += c.supported, s.occluded += c.occluded;
		s.outside += c.outside, s.cost += c.cost_px2;
	}
	s.cost = s.considered ? s.cost / s.considered : 1e300;
	const bool enough_unoccluded =
	    s.considered >= opts_.min_unoccluded_fraction * (s.considered + s.occluded);
	const int in_image = s.considered + s.occluded;
	const bool enough_in_image = in_image >= opts_.min_in_image_fraction * (in_image + s.outside);
	if (s.considered >= opts_.min_samples && enough_unoccluded && enough_in_image)
		s.score = static_cast<double>(s.supported) / s.considered;
	else
		s.cost = 1e300;  // too little in view to judge: never preferred
	return s;
}

ImageScore ImageVerifier::score(const std::vector<Feature>& features_O,
                                const Eigen::Isometry3d& T_OinL, const SelfOcclusion* occ) const
{
	return score(edgeSamplesOf(features_O, opts_.sample_spacing_mm), T_OinL, occ);
}

}  // namespace mrolr::recog
