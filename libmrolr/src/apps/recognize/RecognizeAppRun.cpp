#include "RecognizeOutput.h"

#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/util/Cli.h>

#include <mrpt/config/CConfigFile.h>
#include <opencv2/imgcodecs.hpp>

#include <mrolr/recog/images/MutualOcclusion.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace mrolr::apps
{
namespace
{
/** A shipped file (config/...) relative to the working directory, or else to the source tree. */

cv::Mat readImage(const std::string& path, int flags)
{
	cv::Mat img = cv::imread(path, flags);
	if (img.empty()) throw std::runtime_error("cannot read image '" + path + "'");
	return img;
}

std::string imageNote(const recog::RecognitionResult& r)
{
	if (!r.image_score) return "";
	std::ostringstream s;
	s << std::fixed << std::setprecision(3) << ", image score " << *r.image_score;
	return s.str();
}

void printMatrix(std::ostream& out, const Eigen::Matrix4d& T)
{
	for (int r = 0; r < 4; ++r)
	{
		out << "    ";
		for (int c = 0; c < 4; ++c) out << std::setw(12) << T(r, c);
		out << "\n";
	}
}
}  // namespace

void RecognizeApp::loadScenes()
{
	for (const auto& p : scene_paths) scenes.push_back(model::loadWireFrame(p));
	if (!scene_paths.empty()) return;
	const auto calib = stereo::loadStereoCalibration(calib_path);
	stereo::SceneOptions so;
	so.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile(scene_config_path)),
	                      "scene");
	// with --support-plane the up direction is known: rims seen edge-on become horizontal circles
	std::optional<Eigen::Vector3d> up_L;
	if (support_plane) up_L = support_plane->n_S;
	const auto s =
	    stereo::reconstructScene(readImage(left_png, cv::IMREAD_GRAYSCALE),
	                             readImage(right_png, cv::IMREAD_GRAYSCALE), calib, so, up_L);
	scenes.push_back(model::sceneToWireFrame(s));
	scenes.back().name = "stereo";
}

int RecognizeApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	if (!demo_dir.empty())
	{
		writeDemo(out);
		return util::kExitOk;
	}
	if (!evaluate_dir.empty()) return runEvaluation(out);
	loadRecognitionOptions();
	for (const auto& p : model_paths) models.push_back(model::loadWireFrame(p));
	loadScenes();
	const bool stereo = scene_paths.empty();
	std::unique_ptr<recog::ImageVerifier> images;
	if (stereo && image_verify)
	{
		image_options.loadFromConfigFile(
		    mrpt::config::CConfigFile(util::requireProjectFile(config_path)), "image_verification");
		images = std::make_unique<recog::ImageVerifier>(
		    readImage(left_png, cv::IMREAD_GRAYSCALE), readImage(right_png, cv::IMREAD_GRAYSCALE),
		    stereo::loadStereoCalibration(calib_path), image_options);
	}
	std::vector<recog::Recognizer> recs;
	for (const auto& m : models) recs.emplace_back(m, options);
	for (const auto& rec : recs)
		results.push_back(images ? recognizeInImages(rec, *images) : rec.searchSweep(scenes));
	if (images && image_options.mutual_occlusion) searchBehindFound(recs, *images);
	if (images && !judgement_prefix.empty()) writeJudgements(recs, *images);
	json ? printJson(out) : printText(out);
	if (!overlay_png.empty())
	{
		const auto calib = stereo::loadStereoCalibration(calib_path);
		const cv::Mat canvas = left_png.empty()
		                           ? cv::Mat(calib.image_size, CV_8UC3, cv::Scalar(30, 30, 30))
		                           : readImage(left_png, cv::IMREAD_COLOR);
		writeOverlay(canvas, calib, scenes, models, results, overlay_png);
	}
	if (!scene3d_path.empty()) writeScene3D(scenes, models, results, scene3d_path);
	return util::kExitOk;
}

recog::RecognitionResult RecognizeApp::recognizeInImages(const recog::Recognizer& rec,
                                                         const recog::ImageVerifier& images,
                                                         bool repeat) const
{
	recog::SceneContext context;  // the plane's normal is the up direction
	context.images = std::cref(images);
	context.repeat = repeat;
	context.plane = support_plane;
	recog::RecognitionResult r = rec.recognize(scenes.front(), context);
	if (r.found) r.scene_index = 0;
	return r;
}

void RecognizeApp::searchBehindFound(const std::vector<recog::Recognizer>& recs,
                                     const recog::ImageVerifier& images)
{
	std::vector<const recog::Recognizer*> ptrs;
	for (const auto& r : recs) ptrs.push_back(&r);
	results = recog::searchBehindFound(
	    ptrs, results, images, image_options.sample_spacing_mm,
	    [&](size_t i, const recog::ImageVerifier& behind)
	    { return recognizeInImages(recs[i], behind, true); });
}

void RecognizeApp::writeJudgements(const std::vector<recog::Recognizer>& recs,
                                   const recog::ImageVerifier& images) const
{
	const cv::Mat grey = readImage(left_png, cv::IMREAD_GRAYSCALE);
	for (size_t i = 0; i < recs.size(); ++i)
	{
		if (!results[i].found) continue;
		const std::string png = judgement_prefix + "_" + results[i].model + ".png";
		const cv::Mat img = recog::drawJudgement(
		    grey, images.image(0), recs[i].edgeSamples(image_options.sample_spacing_mm),
		    results[i].T_OinS, &recs[i].selfOcclusion());
		if (!cv::imwrite(png, img))
			throw std::runtime_error("cannot write judgement '" + png + "'");
	}
}

void RecognizeApp::loadRecognitionOptions()
{
	const mrpt::config::CConfigFile cfg(util::requireProjectFile(config_path));
	options.loadFromConfigFile(cfg, "recognition");
	options.plane.loadFromConfigFile(cfg, "plane_hypotheses");
	if (!plane_hypotheses) options.plane.enable = false;
}

void RecognizeApp::writeDemo(std::ostream& out) const
{
	namespace fs = std::filesystem;
	const auto objects = sim::makeLabObjects();
	fs::create_directories(fs::path(demo_dir) / "models");
	fs::create_directories(fs::path(demo_dir) / "scenes");
	for (const auto& o : objects)
		model::saveWireFrame(o, (fs::path(demo_dir) / "models" / (o.name + ".wf")).string());
	sim::SceneNoise noise;
	noise.endpoint_sigma_mm = 0.7, noise.fragment_probability = 0.3, noise.missing_fraction = 0.15;
	noise.hide_back_side = true;
	nlohmann::json truth = nlohmann::json::array();
	for (int k = 0; k < 4; ++k)
	{
		const auto ts = sim::makeTableScene(objects, k < 3 ? k : -1, 3, noise, 4242 + k);
		const auto name = "table_" + std::to_string(k);
		model::saveWireFrame(ts.scene, (fs::path(demo_dir) / "scenes" / (name + ".wf")).string());
		truth.push_back({{"scene", name + ".wf"},
		                 {"target", ts.target >= 0 ? objects[ts.target].name : "none"},
		                 {"T", resultJson(
		                           [&]
		                           {
			                           recog::RecognitionResult r;
			                           r.T_OinS = ts.T_OinS;
			                           return r;
		                           }())["T"]},
		                 {"visible_fraction", ts.visible_fraction}});
	}
	std::ofstream((fs::path(demo_dir) / "scenes" / "truth.json").string()) << truth.dump(2) << "\n";
	out << "wrote " << objects.size() << " models and 4 scenes under " << demo_dir << "\n";
}

void RecognizeApp::printText(std::ostream& out) const
{
	out << std::fixed << std::setprecision(3);
	for (const auto& r : results)
	{
		if (!r.found)
		{
			out << r.model << ": not found (best score " << r.score << imageNote(r) << ", " << r.ms
			    << " ms)\n";
			continue;
		}
		const auto rpy = rollPitchYawDeg(r.T_OinS.linear());
		out << r.model << ": found in scene " << r.scene_index.value_or(0)
		    << (r.level ? " at level " + std::to_string(*r.level) : std::string())
		    << (r.origin == recog::Origin::SupportPlane ? " (support-plane hypothesis)" : "")
		    << (r.occluders ? " (behind " + std::to_string(r.occluders) + " found)" : std::string())
		    << (r.ambiguous ? " (ambiguous: " + std::to_string(r.poses.size()) + " poses)"
		                    : std::string())
		    << ", score " << r.score << imageNote(r) << ", confidence " << r.confidence << ", "
		    << r.matched << " segments matched, " << r.ms << " ms\n  T (model -> scene, mm):\n";
		printMatrix(out, r.T_OinS.matrix());
		out << "  roll pitch yaw (deg): " << rpy.transpose()
		    << "\n  translation (mm): " << r.T_OinS.translation().transpose()
		    << "\n  agreeing cliques: " << r.agreeing_cliques << ", spread " << r.spread_rot_deg
		    << " deg, " << r.spread_trans_mm << " mm\n";
	}
}

void RecognizeApp::printJson(std::ostream& out) const
{
	nlohmann::json results_json = nlohmann::json::array();
	for (const auto& r : results) results_json.push_back(resultJson(r));
	out << nlohmann::json{{"results", results_json}}.dump(2) << "\n";
}

}  // namespace mrolr::apps
