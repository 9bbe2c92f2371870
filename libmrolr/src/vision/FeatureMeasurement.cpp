#include <mrolr/geometry/IdealHead.h>
#include <mrolr/vision/FeatureMeasurement.h>

#include <stdexcept>

namespace mrolr::vision
{
using geometry::Side;

bool predictRegions(const geometry::BiSightHead& head, const geometry::HeadAngles& angles,
                    const Eigen::Vector3d& h_pred, const Eigen::Matrix3d& S, const VisionOptions& o,
                    FeatureMeasurement& m)
{
	m.angles = angles;
	try
	{
		m.ellipse_left = projectInnovation(head, Side::Left, angles, h_pred, S, o.search_n_sigma);
		m.ellipse_right = projectInnovation(head, Side::Right, angles, h_pred, S, o.search_n_sigma);
		return true;
	}
	catch (const geometry::GeometryError&)
	{
		return false;  // behind a camera
	}
	catch (const std::invalid_argument&)
	{
		return false;  // vergence outside (0, π/2)
	}
}

namespace
{
/** A best match with a rival within the ambiguity margin elsewhere in the region (repeated
 * texture) is no measurement. */
bool ambiguous(const PatchMatch& m, const VisionOptions& o)
{
	return o.nssd_ambiguity_margin > 0 && m.second_score - m.score < o.nssd_ambiguity_margin;
}
}  // namespace

void matchInRegions(const StereoImages& images, const geometry::BiSightHead& head,
                    const cv::Mat& patch, const VisionOptions& o, NssdMethod method,
                    FeatureMeasurement& m)
{
	m.found = false;
	m.left = searchEllipse(images.left, patch, m.ellipse_left, o.nssd_threshold, method);
	if (!m.left.found || ambiguous(m.left, o)) return;
	m.right = searchEllipse(images.right, patch, m.ellipse_right, o.nssd_threshold, method);
	if (!m.right.found || ambiguous(m.right, o)) return;
	m.pixels = {m.left.uv.x(), m.left.uv.y(), m.right.uv.x(), m.right.uv.y()};
	try
	{
		m.p_GinC0 = head.triangulatePoint(m.pixels, images.angles);
		m.h = geometry::idealHeadMeasure(m.p_GinC0, head.options().interocular_m);
		m.found = true;
	}
	catch (const geometry::GeometryError&)
	{
		// parallel rays or a point behind a camera: not a measurement
	}
	catch (const std::invalid_argument&)
	{
		// the point coincides with the head centre
	}
}

FeatureMeasurement measureInImages(const StereoImages& images, const geometry::BiSightHead& head,
                                   const cv::Mat& patch, const Eigen::Vector3d& h_pred,
                                   const Eigen::Matrix3d& S, const VisionOptions& o,
                                   NssdMethod method)
{
	FeatureMeasurement m;
	if (predictRegions(head, images.angles, h_pred, S, o, m))
		matchInRegions(images, head, patch, o, method, m);
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
