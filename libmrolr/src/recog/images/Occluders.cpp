// Mutual occlusion in the image verification (ImageVerifier::withOccluders, docs/recog.md): the
// image regions covered by objects already recognised in the same stereo pair, with their depth.
#include <mrolr/recog/images/ImageVerifier.h>

#include <opencv2/imgproc.hpp>

#include <limits>

namespace mrolr::recog
{
void EdgeImage::setOccluders(const std::vector<Occluder>& occluders, double margin_mm)
{
	occluder_margin_mm_ = margin_mm;
	occluder_z_.release();
	if (occluders.empty()) return;
	cv::Mat z_map =
	    cv::Mat(edges_.size(), CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
	const Eigen::Isometry3d T_LinC = T_CcvInL_.inverse();
	for (const auto& o : occluders)
	{
		// the hull of the wire-frame's samples is the outline of the object's convex hull (the
		// hull of a cylinder's two rims is its silhouette); samples outside the image count too,
		// projected without distortion (an object half out of the image still covers its half)
		std::vector<cv::Point2f> px;
		Eigen::Vector3d sum = Eigen::Vector3d::Zero();
		const Eigen::Isometry3d T_OinC = T_LinC * o.T_OinL;
		for (const auto& s : o.samples_O)
		{
			const Eigen::Vector3d p = T_OinC * s.p_O;
			sum += p;
			if (p.z() <= 1) continue;
			px.emplace_back(static_cast<float>(K_(0, 0) * p.x() / p.z() + K_(0, 2)),
			                static_cast<float>(K_(1, 1) * p.y() / p.z() + K_(1, 2)));
		}
		if (px.size() < 3) continue;
		const double z = sum.z() / static_cast<double>(o.samples_O.size());
		std::vector<cv::Point2f> hull;
		cv::convexHull(px, hull);
		std::vector<cv::Point> poly;
		for (const auto& h : hull) poly.emplace_back(cvRound(h.x), cvRound(h.y));
		cv::Mat mask = cv::Mat::zeros(edges_.size(), CV_8U);
		cv::fillConvexPoly(mask, poly, cv::Scalar(255));
		const cv::Mat nearer = mask & (z_map > static_cast<float>(z));
		z_map.setTo(cv::Scalar(z), nearer);
	}
	occluder_z_ = z_map;
}

ImageVerifier ImageVerifier::withOccluders(const std::vector<Occluder>& occluders) const
{
	ImageVerifier out = *this;
	for (auto& image : out.images_) image.setOccluders(occluders, opts_.occluder_margin_mm);
	return out;
}

}  // namespace mrolr::recog
