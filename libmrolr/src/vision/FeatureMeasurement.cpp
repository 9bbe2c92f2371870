#include <mrolr/geometry/IdealHead.h>
#include <mrolr/vision/FeatureMeasurement.h>

#include <stdexcept>

namespace mrolr::vision
{
using geometry::Side;

FeatureMeasurement measureInImages(const StereoImages& images, const geometry::BiSightHead& head,
                                   const cv::Mat& patch, const Eigen::Vector3d& h_pred,
                                   const Eigen::Matrix3d& S, const VisionOptions& o,
                                   NssdMethod method)
{
	FeatureMeasurement m;
	m.angles = images.angles;
	try
	{
		const double n = o.search_n_sigma;
		m.ellipse_left = projectInnovation(head, Side::Left, images.angles, h_pred, S, n);
		m.ellipse_right = projectInnovation(head, Side::Right, images.angles, h_pred, S, n);
		m.left = searchEllipse(images.left, patch, m.ellipse_left, o.nssd_threshold, method);
		if (!m.left.found) return m;
		m.right = searchEllipse(images.right, patch, m.ellipse_right, o.nssd_threshold, method);
		if (!m.right.found) return m;
		m.pixels = {m.left.uv.x(), m.left.uv.y(), m.right.uv.x(), m.right.uv.y()};
		m.p_GinC0 = head.triangulatePoint(m.pixels, images.angles);
		m.h = geometry::idealHeadMeasure(m.p_GinC0, head.options().interocular_m);
		m.found = true;
	}
	catch (const geometry::GeometryError&)
	{
		m.found = false;  // behind a camera or parallel rays: not a measurement
	}
	catch (const std::invalid_argument&)
	{
		m.found = false;  // idealHeadInverse/Measure outside their domain
	}
	return m;
}

FeatureMeasurement measureWithHead(StereoHeadDevice& device, const geometry::BiSightHead& head,
                                   const cv::Mat& patch, const Eigen::Vector3d& h_pred,
                                   const Eigen::Matrix3d& S, const VisionOptions& options)
{
	try
	{
		const Eigen::Vector3d p = geometry::idealHeadInverse(h_pred, head.options().interocular_m);
		device.moveTo(head.fixate(p));
	}
	catch (const std::invalid_argument&)  // vergence outside (0, π/2): no point to look at
	{
		FeatureMeasurement none;
		none.angles = device.angles();
		return none;
	}
	catch (const geometry::GeometryError&)  // beyond a joint limit or too close to the head
	{
		FeatureMeasurement none;
		none.angles = device.angles();
		return none;
	}
	return measureInImages(device.grab(), head, patch, h_pred, S, options);
}

}  // namespace mrolr::vision
