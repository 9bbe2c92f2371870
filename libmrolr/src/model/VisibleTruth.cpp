#include <mrolr/model/VisibleTruth.h>
#include <mrolr/model/WireFrameSampling.h>

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace mrolr::model
{
namespace
{
/** One camera that sees the samples: its pose relative to L (OpenCV axes), intrinsics, depth. */
struct View
{
	cv::Matx33d R_CamFromLcv = cv::Matx33d::eye();
	cv::Vec3d t_LinCam_mm = {};
	cv::Matx33d K;
	cv::Vec<double, 5> D;
	const cv::Mat* depth_mm = nullptr;
};

using Visibility = std::function<std::vector<bool>(const std::vector<Eigen::Vector3d>&)>;

double depthAt(const cv::Mat& d, int r, int c)
{
	return d.type() == CV_16U ? d.at<uint16_t>(r, c) : d.at<float>(r, c);
}

/** Is each point (thesis L, mm) seen by the camera: in the image, and the rendered depth near its
 * pixel agrees with its depth? */
std::vector<bool> seen(const std::vector<Eigen::Vector3d>& P, const View& cam, double tol)
{
	std::vector<cv::Point3d> pc;  // camera's OpenCV axes: x right, y down
	for (const auto& p : P)
		pc.emplace_back(cam.R_CamFromLcv * cv::Vec3d(-p.x(), -p.y(), p.z()) + cam.t_LinCam_mm);
	std::vector<cv::Point2d> px;
	if (!pc.empty())
		cv::projectPoints(pc, cv::Vec3d(), cv::Vec3d(), cv::Mat(cam.K), cv::Mat(cam.D), px);
	const cv::Mat& depth = *cam.depth_mm;
	std::vector<bool> out(P.size(), false);
	for (size_t i = 0; i < P.size(); ++i)
	{
		const int u = cvRound(px[i].x), v = cvRound(px[i].y);
		if (pc[i].z <= 0 || u < 1 || v < 1 || u >= depth.cols - 1 || v >= depth.rows - 1) continue;
		for (int dv = -1; dv <= 1 && !out[i]; ++dv)
			for (int du = -1; du <= 1 && !out[i]; ++du)
				out[i] = std::abs(depthAt(depth, v + dv, u + du) - pc[i].z) <= tol;
	}
	return out;
}

/** Calls piece(i, j) for every run [i, j) of visible samples. */
void forRuns(const std::vector<bool>& vis, const std::function<void(size_t, size_t)>& piece)
{
	for (size_t i = 0; i < vis.size();)
	{
		if (!vis[i])
		{
			++i;
			continue;
		}
		size_t j = i;
		while (j < vis.size() && vis[j]) ++j;
		piece(i, j);
		i = j;
	}
}

void clipLine(const Line3& l, const Visibility& visible, const VisibilityOptions& o, WireFrame& out)
{
	const size_t n = std::max<size_t>(2, static_cast<size_t>(std::ceil(l.length() / o.step_mm)));
	std::vector<Eigen::Vector3d> P;
	for (size_t i = 0; i < n; ++i) P.push_back(l.p1 + (l.p2 - l.p1) * ((i + 0.5) / n));
	forRuns(visible(P),
	        [&](size_t i, size_t j)
	        {
		        const Line3 piece{0, l.p1 + (l.p2 - l.p1) * (double(i) / n),
		                          l.p1 + (l.p2 - l.p1) * (double(j) / n)};
		        if (piece.length() >= o.min_piece_mm) out.lines.push_back(piece);
	        });
}

void clipConic(const Conic3& c, const Visibility& visible, const VisibilityOptions& o,
               WireFrame& out)
{
	const size_t n = std::max<size_t>(8, static_cast<size_t>(std::ceil(arcLength(c) / o.step_mm)));
	const double dt = (c.t2 - c.t1) / n;
	std::vector<Eigen::Vector3d> P;
	for (size_t i = 0; i < n; ++i) P.push_back(c.pointAt(c.t1 + (i + 0.5) * dt));
	forRuns(visible(P),
	        [&](size_t i, size_t j)
	        {
		        Conic3 piece = c;
		        piece.t1 = c.t1 + i * dt;
		        piece.t2 = c.t1 + j * dt;
		        if (arcLength(piece) >= o.min_piece_mm) out.conics.push_back(piece);
	        });
}

void checkInputs(const WireFrame& truth_L, const cv::Mat& depth_mm, const cv::Size& size,
                 const char* which)
{
	if (truth_L.frame != WireFrameFrame::LeftCamera)
		throw std::invalid_argument("visibleWireFrame: the truth must be in frame left_camera");
	if (depth_mm.size() != size || (depth_mm.type() != CV_16U && depth_mm.type() != CV_32F))
		throw std::invalid_argument(std::string("visibleWireFrame: the ") + which +
		                            " depth image must be 16-bit or float mm of the calibration's "
		                            "size " +
		                            std::to_string(size.width) + "x" + std::to_string(size.height));
}

WireFrame clip(const WireFrame& truth_L, const Visibility& visible, const VisibilityOptions& o)
{
	WireFrame out;
	out.name = truth_L.name;
	out.frame = truth_L.frame;
	for (const auto& l : truth_L.lines) clipLine(l, visible, o, out);
	for (const auto& c : truth_L.conics) clipConic(c, visible, o, out);
	int id = 1;
	for (auto& l : out.lines) l.id = id++;
	for (auto& c : out.conics) c.id = id++;
	return out;
}

View leftView(const stereo::StereoCalibration& calib, const cv::Mat& depth)
{
	return {cv::Matx33d::eye(), {}, calib.K_left, calib.D_left, &depth};
}
}  // namespace

WireFrame visibleWireFrame(const WireFrame& truth_L, const cv::Mat& depth_mm,
                           const stereo::StereoCalibration& calib, const VisibilityOptions& o)
{
	checkInputs(truth_L, depth_mm, calib.image_size, "left");
	const View left = leftView(calib, depth_mm);
	return clip(
	    truth_L, [&](const auto& P) { return seen(P, left, o.depth_tol_mm); }, o);
}

WireFrame visibleInBothCameras(const WireFrame& truth_L, const cv::Mat& depth_left_mm,
                               const cv::Mat& depth_right_mm,
                               const stereo::StereoCalibration& calib, const VisibilityOptions& o)
{
	checkInputs(truth_L, depth_left_mm, calib.image_size, "left");
	checkInputs(truth_L, depth_right_mm, calib.image_size, "right");
	const View left = leftView(calib, depth_left_mm);
	const View right{calib.R_RfromL, calib.t_LinR_mm, calib.K_right, calib.D_right,
	                 &depth_right_mm};
	return clip(
	    truth_L,
	    [&](const auto& P)
	    {
		    auto vis = seen(P, left, o.depth_tol_mm);
		    const auto vr = seen(P, right, o.depth_tol_mm);
		    for (size_t i = 0; i < vis.size(); ++i) vis[i] = vis[i] && vr[i];
		    return vis;
	    },
	    o);
}

}  // namespace mrolr::model
