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
double depthAt(const cv::Mat& d, int r, int c)
{
	return d.type() == CV_16U ? d.at<uint16_t>(r, c) : d.at<float>(r, c);
}

/** Is each point (thesis L, mm) seen by the camera: in the image, and the rendered depth near its
 * pixel agrees with its depth? */
std::vector<bool> seen(const std::vector<Eigen::Vector3d>& P, const cv::Mat& depth,
                       const stereo::StereoCalibration& calib, double tol)
{
	std::vector<cv::Point3d> cv_pts;  // OpenCV camera axes: x right, y down
	for (const auto& p : P) cv_pts.emplace_back(-p.x(), -p.y(), p.z());
	std::vector<cv::Point2d> px;
	if (!cv_pts.empty())
		cv::projectPoints(cv_pts, cv::Vec3d(), cv::Vec3d(), cv::Mat(calib.K_left),
		                  cv::Mat(calib.D_left), px);
	std::vector<bool> out(P.size(), false);
	for (size_t i = 0; i < P.size(); ++i)
	{
		const int u = cvRound(px[i].x), v = cvRound(px[i].y);
		if (P[i].z() <= 0 || u < 1 || v < 1 || u >= depth.cols - 1 || v >= depth.rows - 1) continue;
		for (int dv = -1; dv <= 1 && !out[i]; ++dv)
			for (int du = -1; du <= 1 && !out[i]; ++du)
				out[i] = std::abs(depthAt(depth, v + dv, u + du) - P[i].z()) <= tol;
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

void clipLine(const Line3& l, const cv::Mat& depth, const stereo::StereoCalibration& calib,
              const VisibilityOptions& o, WireFrame& out)
{
	const size_t n = std::max<size_t>(2, static_cast<size_t>(std::ceil(l.length() / o.step_mm)));
	std::vector<Eigen::Vector3d> P;
	for (size_t i = 0; i < n; ++i) P.push_back(l.p1 + (l.p2 - l.p1) * ((i + 0.5) / n));
	forRuns(seen(P, depth, calib, o.depth_tol_mm),
	        [&](size_t i, size_t j)
	        {
		        const Line3 piece{0, l.p1 + (l.p2 - l.p1) * (double(i) / n),
		                          l.p1 + (l.p2 - l.p1) * (double(j) / n)};
		        if (piece.length() >= o.min_piece_mm) out.lines.push_back(piece);
	        });
}

void clipConic(const Conic3& c, const cv::Mat& depth, const stereo::StereoCalibration& calib,
               const VisibilityOptions& o, WireFrame& out)
{
	const size_t n = std::max<size_t>(8, static_cast<size_t>(std::ceil(arcLength(c) / o.step_mm)));
	const double dt = (c.t2 - c.t1) / n;
	std::vector<Eigen::Vector3d> P;
	for (size_t i = 0; i < n; ++i) P.push_back(c.pointAt(c.t1 + (i + 0.5) * dt));
	forRuns(seen(P, depth, calib, o.depth_tol_mm),
	        [&](size_t i, size_t j)
	        {
		        Conic3 piece = c;
		        piece.t1 = c.t1 + i * dt;
		        piece.t2 = c.t1 + j * dt;
		        if (arcLength(piece) >= o.min_piece_mm) out.conics.push_back(piece);
	        });
}
}  // namespace

WireFrame visibleWireFrame(const WireFrame& truth_L, const cv::Mat& depth_mm,
                           const stereo::StereoCalibration& calib, const VisibilityOptions& o)
{
	if (truth_L.frame != WireFrameFrame::LeftCamera)
		throw std::invalid_argument("visibleWireFrame: the truth must be in frame left_camera");
	if (depth_mm.size() != calib.image_size ||
	    (depth_mm.type() != CV_16U && depth_mm.type() != CV_32F))
		throw std::invalid_argument(
		    "visibleWireFrame: the depth image must be 16-bit or float mm of the calibration's "
		    "size " +
		    std::to_string(calib.image_size.width) + "x" + std::to_string(calib.image_size.height));
	WireFrame out;
	out.name = truth_L.name;
	out.frame = truth_L.frame;
	for (const auto& l : truth_L.lines) clipLine(l, depth_mm, calib, o, out);
	for (const auto& c : truth_L.conics) clipConic(c, depth_mm, calib, o, out);
	int id = 1;
	for (auto& l : out.lines) l.id = id++;
	for (auto& c : out.conics) c.id = id++;
	return out;
}

}  // namespace mrolr::model
