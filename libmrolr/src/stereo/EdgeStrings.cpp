#include <mrolr/stereo/EdgeStrings.h>
#include <mrolr/util/OptionsBinder.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/edge_drawing.hpp>

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace mrolr::stereo
{
namespace
{
/** Bilinear sample of a CV_32F image; 0 outside. */
double sample(const cv::Mat& img, double x, double y)
{
	const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
	if (x0 < 0 || y0 < 0 || x0 + 1 >= img.cols || y0 + 1 >= img.rows) return 0;
	const double fx = x - x0, fy = y - y0;
	const float* r0 = img.ptr<float>(y0);
	const float* r1 = img.ptr<float>(y0 + 1);
	return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) +
	       fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

/** Gradient images of the smoothed image. */
struct Gradients
{
	cv::Mat gx, gy, mag;
};

Gradients gradients(const cv::Mat& grey, double sigma)
{
	cv::Mat f;
	grey.convertTo(f, CV_32F);
	if (sigma > 0) cv::GaussianBlur(f, f, cv::Size(), sigma);
	Gradients g;
	cv::Sobel(f, g.gx, CV_32F, 1, 0, 3, 0.125);
	cv::Sobel(f, g.gy, CV_32F, 0, 1, 3, 0.125);
	cv::magnitude(g.gx, g.gy, g.mag);
	return g;
}

/** Sub-pixel edgel at chain pixel @p q: parabolic peak of |∇I| along the gradient direction. */
Edgel refine(const Gradients& g, cv::Point q)
{
	const cv::Point2d grad(g.gx.at<float>(q), g.gy.at<float>(q));
	Edgel e{cv::Point2d(q), grad};
	const double n = std::hypot(grad.x, grad.y);
	if (n <= 0) return e;
	const cv::Point2d u = grad / n;
	const double m0 = g.mag.at<float>(q);
	const double mm = sample(g.mag, q.x - u.x, q.y - u.y), mp = sample(g.mag, q.x + u.x, q.y + u.y);
	const double den = mm - 2 * m0 + mp;
	if (den < 0)
	{
		const double delta = std::clamp(0.5 * (mm - mp) / den, -0.5, 0.5);
		e.p += delta * u;
	}
	return e;
}

cv::Ptr<cv::ximgproc::EdgeDrawing> makeDetector(const EdgeOptions& o)
{
	auto ed = cv::ximgproc::createEdgeDrawing();
	ed->params.EdgeDetectionOperator = cv::ximgproc::EdgeDrawing::SOBEL;
	ed->params.GradientThresholdValue = o.gradient_threshold;
	ed->params.AnchorThresholdValue = o.anchor_threshold;
	ed->params.Sigma = static_cast<float>(o.blur_sigma_px);
	ed->params.MinPathLength = o.min_string_edgels;
	return ed;
}
}  // namespace

cv::Point2d Edgel::tangent() const
{
	const double n = std::hypot(grad.x, grad.y);
	return n > 0 ? cv::Point2d(-grad.y / n, grad.x / n) : cv::Point2d(1, 0);
}

namespace
{
using O = EdgeOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& edgeOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("blur_sigma_px", &O::blur_sigma_px, 0, 10, kOpt)
	    .integer("gradient_threshold", &O::gradient_threshold, 0, 100000, kOpt)
	    .integer("anchor_threshold", &O::anchor_threshold, 0, 100000, kOpt)
	    .integer("min_string_edgels", &O::min_string_edgels, 2, 1000000, kOpt);
	return b;
}
}  // namespace

void EdgeOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                    const std::string& section)
{
	edgeOptionsBinder().load(cfg, section, *this);
}

void EdgeOptions::dump(std::ostream& out) const
{
	edgeOptionsBinder().dump(out, *this);
}

std::vector<EdgeString> detectEdgeStrings(const cv::Mat& grey, const EdgeOptions& o)
{
	if (grey.empty() || grey.type() != CV_8UC1)
		throw std::invalid_argument("edge detection needs a non-empty 8-bit grey image");
	auto ed = makeDetector(o);
	ed->detectEdges(grey);
	const Gradients g = gradients(grey, o.blur_sigma_px);
	std::vector<EdgeString> out;
	for (const auto& chain : ed->getSegments())
	{
		if (static_cast<int>(chain.size()) < o.min_string_edgels) continue;
		EdgeString s;
		s.reserve(chain.size());
		for (const auto& q : chain) s.push_back(refine(g, q));
		out.push_back(std::move(s));
	}
	return out;
}

}  // namespace mrolr::stereo
