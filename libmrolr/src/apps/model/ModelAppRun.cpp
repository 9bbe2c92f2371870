#include <mrolr/apps/ModelApp.h>
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/model/AutoCliques.h>
#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/ModelRender.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/VisibleTruth.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/util/Cli.h>

#include <mrpt/config/CConfigFile.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <ostream>

namespace mrolr::apps
{
namespace
{

mrpt::config::CConfigFile openConfig(const std::string& path)
{
	return mrpt::config::CConfigFile(util::requireProjectFile(path));
}

template <typename Opt>
Opt loadOptions(const std::string& path, const std::string& section)
{
	Opt o;
	o.loadFromConfigFile(openConfig(path), section);
	return o;
}

cv::Mat readImage(const std::string& path)
{
	cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
	if (img.empty()) throw std::runtime_error("cannot read image '" + path + "'");
	return img;
}

nlohmann::json qualityJson(const model::ModelQuality& q)
{
	return {{"true_length_mm", q.true_length_mm},
	        {"recovered_length_mm", q.recovered_length_mm},
	        {"recovered_fraction", q.recovered_fraction},
	        {"model_features", q.model_features},
	        {"false_segments", q.false_features},
	        {"median_endpoint_error_mm", q.median_endpoint_error_mm},
	        {"max_endpoint_error_mm", q.max_endpoint_error_mm},
	        {"conics_compared", q.conics_compared},
	        {"median_conic_radius_error_mm", q.median_conic_radius_error_mm}};
}

Eigen::Vector3d v3(const std::vector<double>& v, size_t i)
{
	return {v[i], v[i + 1], v[i + 2]};
}

geometry::HeadAngles anglesFromDeg(const std::vector<double>& d)
{
	const double k = M_PI / 180;
	return {d[0] * k, d[1] * k, d[2] * k, d[3] * k};
}
}  // namespace

int ModelApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	report = {{"command", command}};
	int rc = util::kExitOk;
	if (command == "build")
		rc = runBuild();
	else if (command == "scene")
		rc = runScene();
	else if (command == "edit")
		rc = runEdit(out);
	else if (command == "cliques")
		rc = runCliques();
	else if (command == "show")
		rc = runShow();
	else
		rc = runStats();
	report["lines"] = result.lines.size();
	report["conics"] = result.conics.size();
	report["cliques"] = result.cliques.size();
	report["total_length_mm"] = model::totalLength(result);
	if (json)
		out << report.dump(2) << "\n";
	else
		for (const auto& [k, v] : report.items()) out << k << " " << v.dump() << "\n";
	return rc;
}

void ModelApp::addStatsToReport(const model::WireFrame& truth)
{
	addStatsToReport(result, truth);
}

void ModelApp::addStatsToReport(const model::WireFrame& m, const model::WireFrame& truth)
{
	quality =
	    model::compareToTruth(m, truth, loadOptions<model::QualityOptions>(config_path, "quality"));
	report["quality"] = qualityJson(*quality);
}

int ModelApp::runBuild()
{
	const auto set = model::loadTurntableSet(turntable_dir);
	const auto so = loadOptions<stereo::SceneOptions>(config_path, "scene");
	const auto to = loadOptions<model::TurntableOptions>(config_path, "turntable");
	const std::string truth = truth_path.empty() ? set.truth_path : truth_path;
	result = align == "recog" ? buildByRecognition(set, so, to, truth)
	                          : model::buildFromTurntable(set, so, to);
	model::addAutomaticCliques(result, loadOptions<model::CliqueOptions>(config_path, "cliques"));
	model::saveWireFrame(result, out_path);
	report["views"] = set.views.size();
	report["align"] = align;
	report["out"] = out_path;
	if (!truth.empty()) addStatsToReport(model::loadWireFrame(truth));
	return util::kExitOk;
}

stereo::StereoCalibration ModelApp::viewCalibration() const
{
	if (!calib_path.empty()) return stereo::loadStereoCalibration(calib_path);
	const geometry::BiSightHead head(
	    geometry::BiSightOptions::fromFile(util::requireProjectFile(bisight_path)));
	return stereo::calibrationFromHead(head, anglesFromDeg(*head_deg));
}

int ModelApp::runScene()
{
	std::optional<geometry::BiSightHead> head;
	if (head_deg)
		head.emplace(geometry::BiSightOptions::fromFile(util::requireProjectFile(bisight_path)));
	const auto calib = viewCalibration();
	const auto so = loadOptions<stereo::SceneOptions>(config_path, "scene");
	std::optional<Eigen::Vector3d> up_L;  // C0's up (+y) in L: horizontal circles need it
	if (head)
		up_L = head->T_LinC0(anglesFromDeg(*head_deg)).linear().transpose() * Eigen::Vector3d::UnitY();
	const auto scene =
	    stereo::reconstructScene(readImage(left_png), readImage(right_png), calib, so, up_L);
	result = model::sceneToWireFrame(scene);
	if (head) result = model::leftCameraToC0(result, *head, anglesFromDeg(*head_deg));
	model::saveWireFrame(result, out_path);
	report["frame"] = model::frameName(result.frame);
	report["edge_strings_left"] = scene.left_strings;
	report["edge_matches"] = scene.matches;
	report["horizontal_circles"] = scene.circle_features;
	report["out"] = out_path;
	if (!truth_path.empty()) statsAgainstTruth(out_path);
	return util::kExitOk;
}

int ModelApp::runEdit(std::ostream& out)
{
	result = model::loadWireFrame(model_path);
	size_t removed = remove_ids.empty() ? 0 : model::removeIds(result, remove_ids);
	for (const auto& b : remove_boxes) removed += model::removeInBox(result, v3(b, 0), v3(b, 3));
	for (const auto& l : add_lines) model::addLine(result, v3(l, 0), v3(l, 3));
	for (const auto& c : add_conics)
		model::addConic(result, {0, v3(c, 0), v3(c, 3), v3(c, 6), c[9], c[10], c[11], c[12]});
	if (grasp) model::setGrasp(result, v3(*grasp, 0), (*grasp)[3], (*grasp)[4], (*grasp)[5]);
	const size_t merged =
	    merge ? model::mergeDuplicates(
	                result, loadOptions<model::TurntableOptions>(config_path, "turntable").merge)
	          : 0;
	if (list) model::listFeatures(result, out);
	model::saveWireFrame(result, out_path);
	report["removed"] = removed;
	report["merged_away"] = merged;
	report["out"] = out_path;
	return util::kExitOk;
}

int ModelApp::runCliques()
{
	result = model::loadWireFrame(model_path);
	if (replace) result.cliques.clear();
	const auto o = loadOptions<model::CliqueOptions>(config_path, "cliques");
	report["manual_cliques"] = result.cliques.size();
	report["added_cliques"] = model::addAutomaticCliques(result, o);
	report["uncovered_directions"] = model::uncoveredDirections(result, o).size();
	report["directions"] = model::viewingDirections(o).size();
	model::saveWireFrame(result, out_path);
	report["out"] = out_path;
	return util::kExitOk;
}

int ModelApp::runShow()
{
	result = model::loadWireFrame(model_path);
	auto o = model::defaultDrawOptions(result.frame);
	if (azimuth_deg) o.azimuth_deg = *azimuth_deg;
	if (elevation_deg) o.elevation_deg = *elevation_deg;
	if (!png_path.empty()) model::saveWireFramePng(result, o, png_path), report["png"] = png_path;
	if (!scene3d_path.empty())
		model::saveWireFrameScene(result, scene3d_path), report["scene3d"] = scene3d_path;
	return util::kExitOk;
}

int ModelApp::runStats()
{
	result = model::loadWireFrame(model_path);
	report["frame"] = model::frameName(result.frame);
	if (!truth_path.empty()) statsAgainstTruth(model_path);
	return util::kExitOk;
}

model::WireFrame ModelApp::inFrameOf(const model::WireFrame& m, const model::WireFrame& truth,
                                     const std::string& name) const
{
	if (m.frame == model::WireFrameFrame::C0 && head_deg &&
	    truth.frame == model::WireFrameFrame::LeftCamera)
	{
		// a scene model written with --head: back into the left camera of that view
		const geometry::BiSightHead head(
		    geometry::BiSightOptions::fromFile(util::requireProjectFile(bisight_path)));
		const Eigen::Isometry3d T_C0inL_mm =
		    geometry::inMm(head.T_LinC0(anglesFromDeg(*head_deg)).inverse());
		return model::transformWireFrame(m, T_C0inL_mm, model::WireFrameFrame::LeftCamera);
	}
	if (m.frame != truth.frame)
		throw std::runtime_error("stats: " + name + " is in frame " + model::frameName(m.frame) +
		                         " but " + truth_path + " in frame " +
		                         model::frameName(truth.frame));
	return m;
}

void ModelApp::statsAgainstTruth(const std::string& name)
{
	auto truth = model::loadWireFrame(truth_path);
	const auto compared = inFrameOf(result, truth, name);
	if (!depth_png.empty())
	{
		const auto read = [](const std::string& png)
		{
			const cv::Mat d = cv::imread(png, cv::IMREAD_UNCHANGED);
			if (d.empty()) throw std::runtime_error("cannot read depth image " + png);
			return d;
		};
		const cv::Mat depth = read(depth_png);
		truth = depth_right_png.empty()
		            ? model::visibleWireFrame(truth, depth, viewCalibration())
		            : model::visibleInBothCameras(truth, depth, read(depth_right_png),
		                                          viewCalibration());
		report["visible_truth_length_mm"] = model::totalLength(truth);
		report["visible_in"] = depth_right_png.empty() ? "left" : "both";
	}
	addStatsToReport(compared, truth);
	if (per_feature) report["truth_features"] = perFeatureJson(compared, truth);
}

nlohmann::json ModelApp::perFeatureJson(const model::WireFrame& m,
                                        const model::WireFrame& truth) const
{
	nlohmann::json a = nlohmann::json::array();
	const auto o = loadOptions<model::QualityOptions>(config_path, "quality");
	for (const auto& f : model::recoveryPerFeature(m, truth, o))
	{
		nlohmann::json j = {{"kind", f.conic ? "conic" : "line"},
		                    {"id", f.id},
		                    {"length_mm", f.length_mm},
		                    {"recovered_mm", f.recovered_mm},
		                    {"mid_mm", {f.mid.x(), f.mid.y(), f.mid.z()}}};
		if (!f.conic)
			j["p1_mm"] = {f.p1.x(), f.p1.y(), f.p1.z()}, j["p2_mm"] = {f.p2.x(), f.p2.y(), f.p2.z()};
		if (!f.conic && truth.frame != model::WireFrameFrame::Object && f.p1.z() > 0 &&
		    f.p2.z() > 0)
		{
			// camera frames: image direction of the line (u ∝ −x/z, v ∝ −y/z)
			const double du = f.p2.x() / f.p2.z() - f.p1.x() / f.p1.z(),
			             dv = f.p2.y() / f.p2.z() - f.p1.y() / f.p1.z();
			j["image_angle_deg"] = std::atan2(std::abs(dv), std::abs(du)) * 180 / M_PI;
		}
		a.push_back(j);
	}
	return a;
}

}  // namespace mrolr::apps
