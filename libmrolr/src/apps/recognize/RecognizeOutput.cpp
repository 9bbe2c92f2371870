#include "RecognizeOutput.h"

#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/util/JsonOptional.h>

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace mrolr::apps
{
namespace
{
const cv::Scalar kColours[] = {{0, 0, 255},   {0, 200, 0},   {255, 0, 0},
                               {0, 200, 255}, {255, 0, 255}, {255, 255, 0}};

std::vector<cv::Point2d> project(const std::vector<Eigen::Vector3d>& p_L,
                                 const stereo::StereoCalibration& calib)
{
	std::vector<cv::Point3d> p_cv;
	for (const auto& p : p_L)
		// thesis L -> OpenCV camera; points far outside the view are dropped because the
		// distortion polynomial folds them back into the image
		if (p.z() > 1 && std::abs(p.x()) < p.z() && std::abs(p.y()) < p.z())
			p_cv.emplace_back(-p.x(), -p.y(), p.z());
	std::vector<cv::Point2d> px;
	if (p_cv.empty()) return px;
	cv::projectPoints(p_cv, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), calib.K_left, calib.D_left, px);
	return px;
}

void drawWireFrame(cv::Mat& img, const model::WireFrame& wf, const stereo::StereoCalibration& calib,
                   const cv::Scalar& colour, int thickness)
{
	for (const auto& pl : polylinesOf(wf))
	{
		const auto px = project(pl, calib);
		for (size_t i = 0; i + 1 < px.size(); ++i)
			cv::line(img, px[i], px[i + 1], colour, thickness, cv::LINE_AA);
	}
}

mrpt::opengl::CSetOfLines::Ptr linesOf(const model::WireFrame& wf, const mrpt::img::TColorf& c)
{
	auto obj = mrpt::opengl::CSetOfLines::Create();
	for (const auto& pl : polylinesOf(wf))
		for (size_t i = 0; i + 1 < pl.size(); ++i)
		{
			const Eigen::Vector3d a = pl[i] / 1000, b = pl[i + 1] / 1000;
			obj->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
		}
	obj->setColor(c);
	return obj;
}
}  // namespace

Eigen::Vector3d rollPitchYawDeg(const Eigen::Matrix3d& R)
{
	const double r2d = 180.0 / M_PI;
	return {std::atan2(R(2, 1), R(2, 2)) * r2d, std::asin(-std::clamp(R(2, 0), -1.0, 1.0)) * r2d,
	        std::atan2(R(1, 0), R(0, 0)) * r2d};
}

nlohmann::json timesJson(const recog::RecognitionTimes& t)
{
	return {{"cliques", t.cliques_ms},
	        {"verify_3d", t.verify_3d_ms},
	        {"image_score", t.image_score_ms},
	        {"image_refine", t.image_refine_ms},
	        {"plane", t.plane_ms}};
}

nlohmann::json resultJson(const recog::RecognitionResult& r)
{
	const auto matrix44 = [](const Eigen::Isometry3d& M)
	{
		nlohmann::json rows = nlohmann::json::array();
		for (int i = 0; i < 4; ++i) rows.push_back({M(i, 0), M(i, 1), M(i, 2), M(i, 3)});
		return rows;
	};
	const nlohmann::json T = matrix44(r.T_OinS);
	nlohmann::json poses = nlohmann::json::array();
	for (const auto& p : r.poses) poses.push_back({{"T", matrix44(p.T_OinS)}, {"support", p.support}});
	const auto rpy = rollPitchYawDeg(r.T_OinS.linear());
	const auto& t = r.T_OinS.translation();
	return {{"model", r.model},
	        {"found", r.found},
	        {"T", T},
	        {"score", r.score},
	        {"matched", r.matched},
	        {"level", r.level},
	        {"ms", r.ms},
	        {"times_ms", timesJson(r.times)},
	        {"image_refinements", r.image_refinements},
	        {"image_refinements_reused", r.image_refinements_reused},
	        {"image_sweeps_reused", r.image_sweeps_reused},
	        {"confidence", r.confidence},
	        {"scene", r.scene_index},
	        {"rpy_deg", {rpy.x(), rpy.y(), rpy.z()}},
	        {"t_mm", {t.x(), t.y(), t.z()}},
	        {"agreeing_cliques", r.agreeing_cliques},
	        {"spread_rot_deg", r.spread_rot_deg},
	        {"spread_trans_mm", r.spread_trans_mm},
	        {"image_score", r.image_score},
	        {"origin", recog::originName(r.origin)},
	        {"occluders", r.occluders},
	        {"ambiguous", r.ambiguous},
	        {"poses", poses}};
}

std::vector<std::vector<Eigen::Vector3d>> polylinesOf(const model::WireFrame& wf)
{
	std::vector<std::vector<Eigen::Vector3d>> out;
	auto add = [&out](const std::vector<model::FeatureSample>& samples)
	{
		out.emplace_back();
		for (const auto& s : samples) out.back().push_back(s.p);
	};
	for (const auto& l : wf.lines) add(model::sampleLine(l, 10.0, 0));
	for (const auto& c : wf.conics) add(model::sampleConic(c, 5.0, 0));
	return out;
}

void writeOverlay(cv::Mat left, const stereo::StereoCalibration& calib,
                  const std::vector<model::WireFrame>& scenes,
                  const std::vector<model::WireFrame>& models,
                  const std::vector<recog::RecognitionResult>& results, const std::string& png)
{
	if (!scenes.empty()) drawWireFrame(left, scenes.front(), calib, {160, 160, 160}, 1);
	for (size_t k = 0; k < models.size(); ++k)
	{
		if (!results[k].found) continue;
		const auto placed = sim::placeInScene(models[k], results[k].T_OinS);
		const auto& colour = kColours[k % 6];
		drawWireFrame(left, placed, calib, colour, 2);
		const auto anchor = project({results[k].T_OinS.translation()}, calib);
		if (!anchor.empty())
			cv::putText(left, models[k].name, anchor[0], cv::FONT_HERSHEY_SIMPLEX, 0.6, colour, 2);
	}
	if (!cv::imwrite(png, left)) throw std::runtime_error("cannot write overlay '" + png + "'");
}

void writeScene3D(const std::vector<model::WireFrame>& scenes,
                  const std::vector<model::WireFrame>& models,
                  const std::vector<recog::RecognitionResult>& results, const std::string& path)
{
	mrpt::opengl::COpenGLScene scene;
	for (const auto& s : scenes) scene.insert(linesOf(s, {0.6f, 0.6f, 0.6f}));
	for (size_t k = 0; k < models.size(); ++k)
	{
		if (!results[k].found) continue;
		const auto& c = kColours[k % 6];
		scene.insert(linesOf(sim::placeInScene(models[k], results[k].T_OinS),
		                     {static_cast<float>(c[2] / 255), static_cast<float>(c[1] / 255),
		                      static_cast<float>(c[0] / 255)}));
	}
	if (!scene.saveToFile(path)) throw std::runtime_error("cannot write 3D scene '" + path + "'");
}

}  // namespace mrolr::apps
