// The robot's decisions in mission.rawlog: the estimate, the navigation searches drawn, the
// recognised model drawn over its view, the planned grasp and the timeline's notes.
#include "DeviceRecorderImpl.h"

#include <mrolr/model/WireFrameSampling.h>

#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <opencv2/imgproc.hpp>

#include <iomanip>
#include <sstream>

namespace mrolr::mission
{
namespace
{
/** Side of the square cut around a search region for its picture (px), and its magnification. */
constexpr int kCrop_px = 120;
constexpr double kZoom = 2.0;

cv::Mat colourOf(const mrpt::img::CImage& img)
{
	cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), c;
	if (m.channels() == 3) return m.clone();
	cv::cvtColor(m, c, cv::COLOR_GRAY2BGR);
	return c;
}

/** A square around @p centre, inside the image. */
cv::Rect cropAround(const Eigen::Vector2d& centre, const cv::Size& size)
{
	const int x = std::clamp(int(centre.x()) - kCrop_px / 2, 0, std::max(0, size.width - kCrop_px));
	const int y = std::clamp(int(centre.y()) - kCrop_px / 2, 0, std::max(0, size.height - kCrop_px));
	return cv::Rect(x, y, std::min(kCrop_px, size.width), std::min(kCrop_px, size.height));
}

/** Pixel @p uv of the full image in the magnified cut @p crop. */
cv::Point2d inCrop(const Eigen::Vector2d& uv, const cv::Rect& crop)
{
	return {(uv.x() - crop.x) * kZoom, (uv.y() - crop.y) * kZoom};
}

void drawEllipse(cv::Mat& img, const vision::ImageEllipse& e, const cv::Rect& crop,
                 const cv::Scalar& colour)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(e.cov);
	const Eigen::Vector2d ax = eig.eigenvalues().cwiseMax(0).cwiseSqrt() * e.n_sigma * kZoom;
	const Eigen::Vector2d v = eig.eigenvectors().col(1);
	const double angle_deg = std::atan2(v.y(), v.x()) * 180 / M_PI;
	cv::ellipse(img, inCrop(e.centre, crop), cv::Size2d(std::max(ax[1], 1.0), std::max(ax[0], 1.0)),
	            angle_deg, 0, 360, colour, 1, cv::LINE_AA);
}

/** Left and right cuts around the search ellipses (yellow), magnified, with the matches green
 * (accepted) or red (refused), side by side, the feature and the verdict written on them. */
cv::Mat searchPicture(const hw::StereoImages& pair, const vision::CycleRecord& c)
{
	const auto& m = c.measurement;
	const cv::Scalar match = c.accepted ? cv::Scalar(0, 200, 0) : cv::Scalar(0, 0, 255);
	cv::Mat sides[2];
	const vision::ImageEllipse* e[2] = {&m.ellipse_left, &m.ellipse_right};
	const vision::PatchMatch* p[2] = {&m.left, &m.right};
	const mrpt::img::CImage* img[2] = {&pair.left, &pair.right};
	for (int i = 0; i < 2; ++i)
	{
		const cv::Mat full = colourOf(*img[i]);
		const cv::Rect crop = cropAround(e[i]->centre, full.size());
		cv::resize(full(crop), sides[i], {}, kZoom, kZoom, cv::INTER_NEAREST);
		drawEllipse(sides[i], *e[i], crop, {0, 220, 255});
		if (p[i]->found)
			cv::drawMarker(sides[i], inCrop(p[i]->uv, crop), match, cv::MARKER_CROSS, 16, 2);
	}
	cv::Mat out;
	cv::hconcat(sides[0], sides[1], out);
	const std::string verdict = c.accepted ? "accepted" : m.found ? "refused" : "not found";
	cv::putText(out, c.label + " " + verdict, {4, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.5, match, 1,
	            cv::LINE_AA);
	return out;
}

std::string measurementText(const vision::CycleRecord& c)
{
	const auto& m = c.measurement;
	std::ostringstream s;
	s << std::fixed << std::setprecision(2) << "feature " << c.label << " (Vs " << c.vs
	  << " rad^3): predicted L (" << m.ellipse_left.centre.x() << ", " << m.ellipse_left.centre.y()
	  << ") R (" << m.ellipse_right.centre.x() << ", " << m.ellipse_right.centre.y() << ") px; ";
	if (m.found)
		s << "matched L (" << m.left.uv.x() << ", " << m.left.uv.y() << ") R (" << m.right.uv.x()
		  << ", " << m.right.uv.y() << ")";
	else
		s << "not found";
	if (c.nis) s << "; NIS " << *c.nis;
	s << "; " << (c.accepted ? "accepted" : c.jointly_rejected ? "refused (joint test)" : "refused");
	return s.str();
}

std::string rows(const Eigen::Isometry3d& T)
{
	std::ostringstream s;
	s << std::setprecision(6);
	for (int i = 0; i < 3; ++i)
		s << "[" << T(i, 0) << " " << T(i, 1) << " " << T(i, 2) << " " << T(i, 3) << "]";
	return s.str();
}

/** A picture as an image observation, its pixels in the images folder as @p name. */
mrpt::obs::CObservationImage::Ptr pictureOf(const std::string& label, const cv::Mat& picture,
                                            const std::string& name, mrpt::Clock::time_point stamp,
                                            const io::ObservationLogWriter& w)
{
	auto img = mrpt::obs::CObservationImage::Create();
	img->sensorLabel = label;
	img->timestamp = stamp;
	img->image = w.external(mrpt::img::CImage(picture, mrpt::img::SHALLOW_COPY), name);
	return img;
}

/** The model carried to T_OinL (mm) drawn on the left image of the view. */
cv::Mat recognisedPicture(const hw::StereoImages& pair, const model::WireFrame& target,
                          const Eigen::Isometry3d& T_OinL, const geometry::PinholeCamera& cam)
{
	cv::Mat img = colourOf(pair.left);
	auto draw = [&](const std::vector<model::FeatureSample>& samples)
	{
		for (size_t i = 0; i + 1 < samples.size(); ++i)
		{
			const Eigen::Vector3d a = T_OinL * samples[i].p, b = T_OinL * samples[i + 1].p;
			if (a.z() <= 1 || b.z() <= 1) continue;
			const auto pa = cam.project(a), pb = cam.project(b);
			cv::line(img, cv::Point2d(pa.x(), pa.y()), cv::Point2d(pb.x(), pb.y()), {0, 0, 255}, 2,
			         cv::LINE_AA);
		}
	};
	for (const auto& l : target.lines) draw(model::sampleLine(l, 10.0, 0));
	for (const auto& c : target.conics) draw(model::sampleConic(c, 5.0, 0));
	return img;
}
}  // namespace

void DeviceRecorder::estimate(const PathSample& s)
{
	auto o = mrpt::obs::CObservationRobotPose::Create();
	o->sensorLabel = "ESTIMATE";
	o->timestamp = impl_->stamp();
	o->pose.mean = mrpt::poses::CPose3D(geometry::vehicleToMrpt(s.estimate));
	// (z, x, φ) → MRPT (x, y, yaw): indices 0, 1, 3 of (x, y, z, yaw, pitch, roll)
	const int at[3] = {0, 1, 3};
	for (int i = 0; i < 3; ++i)
		for (int k = 0; k < 3; ++k) o->pose.cov(at[i], at[k]) = s.P_vv(i, k);
	impl_->post(o);
}

void DeviceRecorder::measurement(const vision::CycleRecord& c)
{
	if (!c.measured) return;
	auto& r = *impl_;
	r.post(io::labelledComment("NAV_MEASUREMENT", measurementText(c), r.stamp()));
	for (auto it = r.recent.rbegin(); it != r.recent.rend(); ++it)
		if (it->angles.pan == c.measurement.angles.pan &&
		    it->angles.tilt == c.measurement.angles.tilt &&
		    it->angles.verg_left == c.measurement.angles.verg_left &&
		    it->angles.verg_right == c.measurement.angles.verg_right)
		{  // drawn and written by the writer thread
			const std::string name = "NAV_SEARCH_" + std::to_string(r.pictures++) + ".png";
			r.log.post([pair = *it, c, name, stamp = r.stamp()](io::ObservationLogWriter& w)
			           { w.write(*pictureOf("NAV_SEARCH", searchPicture(pair, c), name, stamp, w)); });
			return;
		}
}

void DeviceRecorder::recognised(const SearchResult& s, const Eigen::Vector3d& xv,
                                const model::WireFrame& target)
{
	auto& r = *impl_;
	std::ostringstream t;
	t << target.name << " in frame " << (s.frame ? std::to_string(*s.frame) : "none")
	  << ", confidence " << s.recognition.confidence << ", at the estimate (z, x, phi) ("
	  << xv.transpose() << "): T_OinC0 (mm) " << rows(s.T_OinC0_mm) << ", T_OinL (mm) "
	  << rows(s.T_OinL_mm);
	r.post(io::labelledComment("RECOGNISED", t.str(), r.stamp()));
	if (!s.frame) return;
	for (auto it = r.recent.rbegin(); it != r.recent.rend(); ++it)
		if (it->frame == *s.frame)
		{
			const std::string name = "RECOGNISED_" + std::to_string(r.pictures++) + ".png";
			const cv::Mat picture = recognisedPicture(*it, target, s.T_OinL_mm, r.head.camera());
			r.log.post([picture, name, stamp = r.stamp()](io::ObservationLogWriter& w)
			           { w.write(*pictureOf("RECOGNISED", picture, name, stamp, w)); });
			return;
		}
}

void DeviceRecorder::graspPlanned(const RetrievalResult& g)
{
	std::ostringstream t;
	t << std::setprecision(6) << (g.feasible ? "feasible" : "not feasible");
	for (const auto& why : g.reasons) t << "; " << why;
	t << "\nT_GinA (mm) " << rows(g.T_GinA) << "\njoints (d1 mm, q1..q6 deg)";
	for (double v : g.joints.toMmDeg()) t << " " << v;
	t << "\nverified " << g.verified << ", correction " << g.correction_mm << " mm";
	impl_->post(io::labelledComment("GRASP_PLAN", t.str(), impl_->stamp()));
}

void DeviceRecorder::note(const TimelineEvent& e)
{
	impl_->post(io::labelledComment("NOTE", "[" + e.stage + "] " + e.text, impl_->stamp()));
}

}  // namespace mrolr::mission
