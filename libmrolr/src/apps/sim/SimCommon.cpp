#include "SimCommon.h"

#include <mrpt/config/CConfigFile.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace mrolr::apps::simdetail
{
nlohmann::json matrixJson(const Eigen::Isometry3d& T)
{
	nlohmann::json m = nlohmann::json::array();
	for (int r = 0; r < 4; ++r) m.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
	return m;
}

namespace
{
nlohmann::json landmarkJson(const sim::LandmarkView& v)
{
	return {{"name", v.name},
	        {"known", v.known},
	        {"p_LinW", {v.p_LinW.x(), v.p_LinW.y(), v.p_LinW.z()}},
	        {"p_LinC0", {v.p_LinC0.x(), v.p_LinC0.y(), v.p_LinC0.z()}},
	        {"left_px", {v.uL, v.vL}},
	        {"right_px", {v.uR, v.vR}}};
}

/** True when the rendered depth at the object's origin pixel is clearly nearer than any part of
 * the object can be (another object or the scenery stands in front of it). */
bool originOccluded(const sim::ObjectView& v, const sim::StereoFrame& f)
{
	const float d = f.depth_left_m(int(std::lround(v.vL)), int(std::lround(v.uL)));
	return d > 0 && d < v.T_OinL.translation().z() - 0.15;
}

nlohmann::json objectJson(const sim::ObjectView& v, const sim::StereoFrame& f)
{
	return {{"origin_occluded", originOccluded(v, f)},
	        {"name", v.name},
	        {"model", v.model},
	        {"left_px_of_origin", {v.uL, v.vL}},
	        {"T_OinL", matrixJson(v.T_OinL)},
	        {"T_OinC0", matrixJson(v.T_OinC0)}};
}
}  // namespace

nlohmann::json truthJson(const world::World& w, const geometry::BiSightHead& head,
                         const Eigen::Vector3d& xv, const geometry::HeadAngles& a,
                         const sim::StereoFrame& f)
{
	const Eigen::Isometry3d T_C0inW = f.T_LinW * head.T_LinC0(a).inverse();
	nlohmann::json j;
	j["frames"] = "W, C0, L, R: x left, y up, z forward (thesis); metres; T_AinB maps A to B";
	j["vehicle"] = {{"z_m", xv[0]}, {"x_m", xv[1]}, {"phi_deg", xv[2] * 180 / M_PI}};
	j["head_deg"] = {{"pan", a.pan * 180 / M_PI},
	                 {"tilt", a.tilt * 180 / M_PI},
	                 {"verg_left", a.verg_left * 180 / M_PI},
	                 {"verg_right", a.verg_right * 180 / M_PI}};
	j["T_C0inW"] = matrixJson(T_C0inW);
	j["T_LinW"] = matrixJson(f.T_LinW);
	j["T_RinW"] = matrixJson(f.T_RinW);
	const auto& c = head.camera();
	j["intrinsics"] = {{"focal_px_u", c.focal_px_u}, {"focal_px_v", c.focal_px_v},
	                   {"u0_px", c.u0_px},           {"v0_px", c.v0_px},
	                   {"width_px", c.width_px},     {"height_px", c.height_px}};
	j["landmarks"] = nlohmann::json::array();
	for (const auto& v : sim::landmarkViews(w, head, T_C0inW, a, &f))
		if (v.visible) j["landmarks"].push_back(landmarkJson(v));
	j["objects"] = nlohmann::json::array();
	for (const auto& v : sim::objectViews(w, head, T_C0inW, a))
		if (v.visible) j["objects"].push_back(objectJson(v, f));
	j["render_s"] = f.render_s;
	return j;
}

void saveDepthPng(const mrpt::math::CMatrixFloat& depth_m, const std::string& path)
{
	cv::Mat m(int(depth_m.rows()), int(depth_m.cols()), CV_16UC1);
	for (int r = 0; r < m.rows; ++r)
		for (int c = 0; c < m.cols; ++c)
			m.at<uint16_t>(r, c) =
			    uint16_t(std::clamp(std::lround(depth_m(r, c) * 1000.0), 0L, 65535L));
	if (!cv::imwrite(path, m)) throw std::runtime_error("cannot write " + path);
}

void savePair(const mrpt::img::CImage& left, const mrpt::img::CImage& right,
              const std::string& path)
{
	const cv::Mat l = left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat r = right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	cv::Mat pair;
	cv::hconcat(std::vector<cv::Mat>{l, cv::Mat(l.rows, 8, l.type(), cv::Scalar::all(255)), r},
	            pair);
	if (!cv::imwrite(path, pair)) throw std::runtime_error("cannot write " + path);
}

void saveImage(const mrpt::img::CImage& img, const std::string& path)
{
	if (!img.saveToFile(path)) throw std::runtime_error("cannot write " + path);
}

sim::RenderOptions renderOptions(const std::string& sim_config_path)
{
	sim::RenderOptions o;
	if (std::ifstream(sim_config_path).good())
		o.loadFromConfigFile(mrpt::config::CConfigFile(sim_config_path), "render");
	return o;
}

}  // namespace mrolr::apps::simdetail
