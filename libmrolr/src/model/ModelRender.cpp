#include <mrolr/model/ModelRender.h>
#include <mrolr/model/WireFrameSampling.h>

#include <mrpt/opengl/CAxis.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace mrolr::model
{
namespace
{
/** Screen axes (right, down) for the view. */
struct View
{
	Eigen::Vector3d right, down;
	cv::Point2d project(const Eigen::Vector3d& p) const { return {p.dot(right), p.dot(down)}; }
};

View viewOf(WireFrameFrame frame, const DrawOptions& o)
{
	const bool obj = frame == WireFrameFrame::Object;
	const Eigen::Vector3d up = obj ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
	const Eigen::Vector3d h1 =
	    obj ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(-Eigen::Vector3d::UnitZ());
	const Eigen::Vector3d h2 = up.cross(h1);
	const double a = o.azimuth_deg * M_PI / 180, e = o.elevation_deg * M_PI / 180;
	const Eigen::Vector3d d =
	    std::cos(e) * (std::cos(a) * h1 + std::sin(a) * h2) + std::sin(e) * up;
	const Eigen::Vector3d right = up.cross(d).normalized();
	return {right, -d.cross(right).normalized()};
}

/** Maps view coordinates into the image with a margin, same scale on both axes. */
struct Fit
{
	cv::Point2d centre_px;
	double scale = 1;
	cv::Point2d centre;
	cv::Point operator()(const cv::Point2d& q) const
	{
		const cv::Point2d r = centre_px + scale * (q - centre);
		return {cvRound(r.x * 16), cvRound(r.y * 16)};
	}
};

Fit fitTo(const std::vector<cv::Point2d>& pts, const DrawOptions& o)
{
	cv::Rect2d box(0, 0, 1, 1);
	if (!pts.empty())
	{
		double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
		for (const auto& p : pts)
			x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x),
			y1 = std::max(y1, p.y);
		box = cv::Rect2d(x0, y0, x1 - x0, y1 - y0);
	}
	box.width = std::max(box.width, 1e-6);
	box.height = std::max(box.height, 1e-6);
	Fit f;
	f.scale = 0.9 * std::min(o.width_px / box.width, o.height_px / box.height);
	f.centre = {box.x + box.width / 2, box.y + box.height / 2};
	f.centre_px = {o.width_px / 2.0, o.height_px / 2.0};
	return f;
}

void drawPolyline(cv::Mat& img, const std::vector<cv::Point>& poly, const cv::Scalar& colour)
{
	cv::polylines(img, poly, false, colour, 2, cv::LINE_AA, 4);
}
}  // namespace

DrawOptions defaultDrawOptions(WireFrameFrame frame)
{
	DrawOptions o;
	if (frame == WireFrameFrame::Object) o.azimuth_deg = 30, o.elevation_deg = 25;
	return o;
}

cv::Mat drawWireFrame(const WireFrame& wf, const DrawOptions& o)
{
	const View v = viewOf(wf.frame, o);
	const auto samples = sampleWireFrame(wf, 1.0);
	std::vector<cv::Point2d> all;
	for (const auto& s : samples) all.push_back(v.project(s.p));
	const Fit fit = fitTo(all, o);
	cv::Mat img(o.height_px, o.width_px, CV_8UC3, cv::Scalar(255, 255, 255));
	for (const auto& l : wf.lines)
		drawPolyline(img, {fit(v.project(l.p1)), fit(v.project(l.p2))}, cv::Scalar(180, 60, 0));
	for (const auto& c : wf.conics)
	{
		std::vector<cv::Point> poly;
		for (const auto& s : sampleConic(c, 1.0, 0)) poly.push_back(fit(v.project(s.p)));
		drawPolyline(img, poly, cv::Scalar(0, 0, 200));
	}
	if (wf.has_grasp)
		cv::drawMarker(img, fit(v.project(wf.grasp.p_mm)) / 16, cv::Scalar(0, 160, 0),
		               cv::MARKER_CROSS, 20, 2);
	if (!o.show_ids) return img;
	for (size_t i = 0; i < featureCount(wf); ++i)
	{
		const Eigen::Vector3d m =
		    i < wf.lines.size()
		        ? Eigen::Vector3d((wf.lines[i].p1 + wf.lines[i].p2) / 2)
		        : wf.conics[i - wf.lines.size()].pointAt(wf.conics[i - wf.lines.size()].t1);
		cv::putText(img, std::to_string(featureId(wf, i)), fit(v.project(m)) / 16,
		            cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(90, 90, 90), 1, cv::LINE_AA);
	}
	return img;
}

void saveWireFramePng(const WireFrame& wf, const DrawOptions& o, const std::string& path)
{
	bool ok = false;
	try
	{
		ok = cv::imwrite(path, drawWireFrame(wf, o));
	}
	catch (const cv::Exception&)
	{
		ok = false;
	}
	if (!ok) throw std::runtime_error("cannot write image '" + path + "'");
}

mrpt::opengl::CSetOfObjects::Ptr wireFrameObject(const WireFrame& wf)
{
	auto obj = mrpt::opengl::CSetOfObjects::Create();
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setColor_u8(0, 60, 180);
	lines->setLineWidth(2);
	for (const auto& l : wf.lines)
		lines->appendLine(l.p1.x() / 1000, l.p1.y() / 1000, l.p1.z() / 1000, l.p2.x() / 1000,
		                  l.p2.y() / 1000, l.p2.z() / 1000);
	auto arcs = mrpt::opengl::CSetOfLines::Create();
	arcs->setColor_u8(200, 0, 0);
	arcs->setLineWidth(2);
	for (const auto& c : wf.conics)
	{
		const auto s = sampleConic(c, 2.0, 0);
		for (size_t i = 1; i < s.size(); ++i)
			arcs->appendLine(s[i - 1].p.x() / 1000, s[i - 1].p.y() / 1000, s[i - 1].p.z() / 1000,
			                 s[i].p.x() / 1000, s[i].p.y() / 1000, s[i].p.z() / 1000);
	}
	obj->insert(lines);
	obj->insert(arcs);
	return obj;
}

void saveWireFrameScene(const WireFrame& wf, const std::string& path)
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(wireFrameObject(wf));
	auto axes = mrpt::opengl::CAxis::Create(-0.05, -0.05, -0.05, 0.1, 0.1, 0.1, 0.05);
	scene.insert(axes);
	if (!scene.saveToFile(path)) throw std::runtime_error("cannot write 3D scene '" + path + "'");
}

}  // namespace mrolr::model
