// A picture of one hypothesis's judgement in one image (ImageVerifier.h): for looking at why a
// pose scores what it scores.
#include <mrolr/recog/images/ImageVerifier.h>

#include <opencv2/imgproc.hpp>

namespace mrolr::recog
{
cv::Mat drawJudgement(const cv::Mat& grey, const EdgeImage& image,
                      const std::vector<EdgeSample>& samples_O, const Eigen::Isometry3d& T_OinL,
                      const SelfOcclusion* occ)
{
	cv::Mat out;
	if (grey.channels() == 1)
		cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
	else if (grey.channels() == 4)
		cv::cvtColor(grey, out, cv::COLOR_BGRA2BGR);
	else
		out = grey.clone();
	out = 0.5 * out;
	out.setTo(cv::Scalar(255, 255, 255), image.edges());
	for (const auto& j : image.judge(samples_O, T_OinL, occ))
	{
		const cv::Scalar colour = j.hidden      ? cv::Scalar(255, 128, 0)
		                          : j.supported ? cv::Scalar(0, 200, 0)
		                                        : cv::Scalar(0, 0, 255);
		const cv::Point c(static_cast<int>(std::lround(j.px.x)),
		                  static_cast<int>(std::lround(j.px.y)));
		if (j.limb)
			cv::drawMarker(out, c, colour, cv::MARKER_TILTED_CROSS, 5, 1);
		else
			cv::circle(out, c, 2, colour, cv::FILLED);
	}
	return out;
}

}  // namespace mrolr::recog
