#include <mrolr/stereo/DenseEdgeStereo.h>
#include <mrolr/util/OptionsBinder.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace mrolr::stereo
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/** Disparity at a sub-pixel position (nearest pixel), NaN outside or unknown. */
double at(const cv::Mat& d, const cv::Point2d& p)
{
	const int x = cvRound(p.x), y = cvRound(p.y);
	if (x < 0 || y < 0 || x >= d.cols || y >= d.rows) return kNaN;
	return d.at<float>(y, x);
}

/** Median of the samples of one side (at 2..side_offset_px px along @p n: the pixel next to the
 * edge is skipped, SGBM smears disparities by about a pixel at a depth edge), NaN if one is
 * unknown or they disagree. */
double side(const cv::Point2d& p, const cv::Point2d& n, const cv::Mat& d,
            const DenseEdgeOptions& o)
{
	std::vector<double> v;
	for (int k = 2; k <= std::max(2, cvRound(o.side_offset_px)); ++k)
	{
		const double s = at(d, p + k * n);
		if (!std::isfinite(s)) return kNaN;
		v.push_back(s);
	}
	std::sort(v.begin(), v.end());
	if (v.back() - v.front() > o.max_side_spread_px) return kNaN;
	return v[v.size() / 2];
}
}  // namespace

namespace
{
using O = DenseEdgeOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& denseEdgeOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .flag("dense_edge_stereo", &O::enabled, kOpt)
	    .integer("dense_block_size_px", &O::block_size_px, 1, 21, kOpt)
	    .number("dense_min_depth_mm", &O::min_depth_mm, 1, 1e6, kOpt)
	    .number("dense_max_depth_mm", &O::max_depth_mm, 2, 1e7, kOpt)
	    .number("dense_side_offset_px", &O::side_offset_px, 2, 20, kOpt)
	    .number("dense_max_side_spread_px", &O::max_side_spread_px, 0, 100, kOpt)
	    .number("dense_max_disparity_jump_px", &O::max_disparity_jump_px, 0, 1e4, kOpt)
	    .integer("dense_min_run_edgels", &O::min_run_edgels, 2, 1000000, kOpt)
	    .flag("dense_unmatched_only", &O::unmatched_only, kOpt)
	    .flag("dense_require_both_sides", &O::require_both_sides, kOpt);
	return b;
}
}  // namespace

void DenseEdgeOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                         const std::string& section)
{
	denseEdgeOptionsBinder().load(cfg, section, *this);
	if (block_size_px % 2 == 0)
		throw util::ConfigError(util::describeKey(cfg, section, "dense_block_size_px") +
		                        ": must be odd");
	util::requireInRange(cfg, section, "dense_max_depth_mm", max_depth_mm, min_depth_mm + 1, 1e7);
}

void DenseEdgeOptions::dump(std::ostream& out) const
{
	denseEdgeOptionsBinder().dump(out, *this);
}

cv::Mat denseDisparity(const cv::Mat& left_rect, const cv::Mat& right_rect, double d_min_px,
                       double d_max_px, const DenseEdgeOptions& o)
{
	const int min_disp = static_cast<int>(std::floor(d_min_px));
	const int num_disp = 16 * std::max(1, static_cast<int>(std::ceil((d_max_px - min_disp) / 16)));
	const int b = o.block_size_px;
	auto sgbm = cv::StereoSGBM::create(min_disp, num_disp, b, 8 * b * b, 32 * b * b, 1, 63, 10,
	                                   100, 2, cv::StereoSGBM::MODE_SGBM_3WAY);
	// SGBM matches only columns x with x − d inside the right image for every searched d: pad on
	// the left (positive disparities) and on the right (negative ones, verged cameras keep d0 < 0)
	// so that every column is searched, then cut the padding off again
	const int pad_l = std::max(0, min_disp + num_disp), pad_r = std::max(0, -min_disp);
	cv::Mat l, r, d16;
	cv::copyMakeBorder(left_rect, l, 0, 0, pad_l, pad_r, cv::BORDER_REPLICATE);
	cv::copyMakeBorder(right_rect, r, 0, 0, pad_l, pad_r, cv::BORDER_REPLICATE);
	sgbm->compute(l, r, d16);
	d16 = d16.colRange(pad_l, pad_l + left_rect.cols);
	cv::Mat d;
	d16.convertTo(d, CV_32F, 1.0 / 16);
	for (int y = 0; y < d.rows; ++y)
		for (int x = 0; x < d.cols; ++x)
		{
			float& v = d.at<float>(y, x);
			if (d16.at<int16_t>(y, x) < 16 * min_disp || x - v < 0 || x - v > d.cols - 1)
				v = std::numeric_limits<float>::quiet_NaN();
		}
	return d;
}

double edgelDisparity(const Edgel& e, const cv::Mat& disparity, const DenseEdgeOptions& o)
{
	const double g = std::hypot(e.grad.x, e.grad.y);
	if (g <= 0) return kNaN;
	const cv::Point2d n(e.grad.x / g, e.grad.y / g);
	const double a = side(e.p, n, disparity, o), b = side(e.p, -n, disparity, o);
	if (std::isfinite(a) && std::isfinite(b)) return std::max(a, b);
	if (o.require_both_sides) return kNaN;
	return std::isfinite(a) ? a : b;
}

std::vector<std::vector<StereoEdgel>> denseEdgeStrings(const std::vector<EdgeString>& left,
                                                       const std::vector<EdgeMatch>& matches,
                                                       const cv::Mat& disparity,
                                                       const Rectifier& rect,
                                                       const DenseEdgeOptions& o)
{
	std::vector<std::vector<StereoEdgel>> out;
	std::vector<StereoEdgel> run;
	const auto flush = [&]()
	{
		if (static_cast<int>(run.size()) >= o.min_run_edgels) out.push_back(std::move(run));
		run.clear();
	};
	size_t m = 0;  // matches are sorted by (string, edgel)
	for (size_t s = 0; s < left.size(); ++s)
	{
		for (size_t i = 0; i < left[s].size(); ++i)
		{
			while (m < matches.size() && (static_cast<size_t>(matches[m].string) < s ||
			                              (static_cast<size_t>(matches[m].string) == s &&
			                               static_cast<size_t>(matches[m].edgel) < i)))
				++m;
			const bool matched = m < matches.size() &&
			                     static_cast<size_t>(matches[m].string) == s &&
			                     static_cast<size_t>(matches[m].edgel) == i;
			double d = kNaN;
			if (matched && !o.unmatched_only)
				d = matches[m].disparity_px;
			else if (!matched)
				d = edgelDisparity(left[s][i], disparity, o);
			if (!std::isfinite(d) || d <= rect.disparityOffset_px())
			{
				flush();
				continue;
			}
			if (!run.empty() && std::abs(d - run.back().d_px) > o.max_disparity_jump_px) flush();
			const cv::Point2d& p = left[s][i].p;
			run.push_back({p, d, rect.pointInLeftCamera(p.x, p.y, d)});
		}
		flush();
	}
	return out;
}

}  // namespace mrolr::stereo
