#include "RecognizeOutput.h"

#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/JsonOptional.h>

#include <mrpt/config/CConfigFile.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>

namespace mrolr::apps
{
namespace fs = std::filesystem;

namespace
{
/** The value, or "-" when there is none (no images, not found). */
template <class T>
std::string orDash(const std::optional<T>& v)
{
	if (!v) return "-";
	std::ostringstream s;
	s << std::fixed << std::setprecision(2) << *v;
	return s.str();
}

nlohmann::json caseJson(const eval::EvalCase& c)
{
	return {{"scene", c.scene},
	        {"model", c.model},
	        {"present", c.present},
	        {"visible_fraction", c.visible_fraction},
	        {"found", c.found},
	        {"correct", c.correct},
	        {"rot_err_deg", c.rot_err_deg},
	        {"trans_err_mm", c.trans_err_mm},
	        {"score", c.score},
	        {"truth_score", c.truth_score},
	        {"image_score", c.image_score},
	        {"truth_image_score", c.truth_image_score},
	        {"level", c.level},
	        {"origin", recog::originName(c.result.origin)},
	        {"occluders", c.result.occluders},
	        {"ambiguous", c.result.ambiguous},
	        {"levels_skipped", c.levels_skipped},
	        {"score_bound", c.score_bound},
	        {"ms", c.ms},
	        {"times_ms", timesJson(c.result.times)},
	        {"image_refinements", c.result.image_refinements},
	        {"image_refinements_reused", c.result.image_refinements_reused},
	        {"image_sweeps_reused", c.result.image_sweeps_reused}};
}

nlohmann::json objectJson(const eval::EvalObject& o)
{
	recog::RecognitionResult r;
	r.T_OinS = o.T_OinL;
	return {{"model", o.model},
	        {"T_OinL_mm", resultJson(r)["T"]},
	        {"visible_fraction", o.visible_fraction}};
}

/** Writes left/right images, the scene wire-frame, its calibration and truth under DIR/scene_K. */
std::string saveScene(const eval::EvalScene& s, const std::string& dir)
{
	char name[32];
	std::snprintf(name, sizeof(name), "scene_%02d", s.index);
	const fs::path d = fs::path(dir) / name;
	fs::create_directories(d);
	cv::imwrite((d / "left.png").string(), s.left);
	cv::imwrite((d / "right.png").string(), s.right);
	model::saveWireFrame(s.scene, (d / "scene.wf").string());
	mrpt::config::CConfigFile calib((d / "calib.ini").string());
	s.calib.saveToConfigFile(calib, "stereo_calib");
	nlohmann::json objects = nlohmann::json::array();
	for (const auto& o : s.objects) objects.push_back(objectJson(o));
	const auto& n = s.plane_L.n_S;
	const nlohmann::json plane = {n.x(), n.y(), n.z(), s.plane_L.d_mm};
	std::ofstream((d / "truth.json").string())
	    << nlohmann::json{{"objects", objects}, {"support_plane_L", plane}}.dump(2);
	return d.string();
}

nlohmann::json summaryJson(const eval::EvalSummary& s)
{
	return {{"rate_cases", s.rate_cases},
	        {"recognised", s.recognised},
	        {"rate", s.rate},
	        {"absent_cases", s.absent_cases},
	        {"false_positives", s.false_positives},
	        {"wrong_poses", s.wrong_poses},
	        {"recognised_from_plane", s.recognised_from_plane},
	        {"median_rot_err_deg", s.median_rot_err_deg},
	        {"median_trans_err_mm", s.median_trans_err_mm},
	        {"median_ms", s.median_ms},
	        {"max_ms", s.max_ms},
	        {"median_absent_ms", s.median_absent_ms},
	        {"mean_times_ms", timesJson(s.mean_times)}};
}
}  // namespace

int RecognizeApp::runEvaluation(std::ostream& out)
{
	const mrpt::config::CConfigFile cfg(util::requireProjectFile(config_path));
	loadRecognitionOptions();
	eval_options.loadFromConfigFile(cfg, "evaluation");
	eval::SetSearchOptions search{options, std::nullopt};
	if (image_verify)
	{
		image_options.loadFromConfigFile(cfg, "image_verification");
		search.images = image_options;
	}
	if (eval_scenes > 0) eval_options.scenes = eval_scenes;
	if (eval_seed >= 0) eval_options.seed = static_cast<unsigned>(eval_seed);
	const auto gen = eval::makeSceneGenerator(eval_options, scene_config_path);
	models = truth_models ? eval::truthModels(*gen) : eval::databaseModels(*gen, model_paths);
	eval_cases = eval::evaluateSet(*gen, models, search,
	                               [this](const eval::EvalScene& s, const auto& found)
	                               { writeEvaluationScene(s, found); });
	eval_summary = eval::summarize(eval_cases, eval_options);
	writeEvaluation(out);
	return util::kExitOk;
}

void RecognizeApp::writeEvaluationScene(const eval::EvalScene& s,
                                        const std::vector<recog::RecognitionResult>& found) const
{
	const std::string d = saveScene(s, evaluate_dir);
	cv::Mat colour;
	cv::cvtColor(s.left, colour, cv::COLOR_GRAY2BGR);
	writeOverlay(colour, s.calib, {s.scene}, models, found, d + "/overlay.png");
}

void RecognizeApp::writeEvaluation(std::ostream& out) const
{
	nlohmann::json cases = nlohmann::json::array();
	for (const auto& c : eval_cases) cases.push_back(caseJson(c));
	const nlohmann::json summary = summaryJson(eval_summary);
	std::ofstream((fs::path(evaluate_dir) / "cases.json").string()) << cases.dump(1) << "\n";
	std::ofstream((fs::path(evaluate_dir) / "summary.json").string()) << summary.dump(2) << "\n";
	if (json)
	{
		out << nlohmann::json{{"summary", summary}, {"cases", cases}}.dump(2) << "\n";
		return;
	}
	out << std::fixed << std::setprecision(2);
	for (const auto& c : eval_cases)
		if (c.present || c.found)
			out << "scene " << c.scene << " " << c.model << (c.present ? "" : " (absent)")
			    << ": visible " << c.visible_fraction << ", "
			    << (c.found ? (c.correct ? "found" : "WRONG") : "not found")
			    << (c.found && c.result.origin == recog::Origin::SupportPlane ? " (plane)" : "")
			    << (c.found && c.result.occluders ? " (behind found)" : "")
			    << (c.found && c.result.ambiguous ? " (ambiguous)" : "") << ", score " << c.score
			    << " (at truth " << c.truth_score << "), image " << orDash(c.image_score)
			    << " (at truth " << orDash(c.truth_image_score) << "), level " << orDash(c.level)
			    << ", err " << c.rot_err_deg
			    << " deg " << c.trans_err_mm << " mm, " << c.ms << " ms\n";
	const auto& s = eval_summary;
	out << "recognised " << s.recognised << "/" << s.rate_cases << " (" << 100 * s.rate
	    << " %) with visible fraction >= " << eval_options.min_visible_fraction << " ("
	    << s.recognised_from_plane << " by plane hypotheses)"
	    << "; false positives " << s.false_positives << "/" << s.absent_cases << "; wrong poses "
	    << s.wrong_poses << "; median errors " << s.median_rot_err_deg << " deg, "
	    << s.median_trans_err_mm << " mm; per model median " << s.median_ms << " ms (absent "
	    << s.median_absent_ms << " ms, max " << s.max_ms << " ms)\n";
	const auto& t = s.mean_times;
	out << "mean time per model and scene: cliques " << t.cliques_ms << " ms, 3D verification "
	    << t.verify_3d_ms << " ms, image scores " << t.image_score_ms << " ms, image refinement "
	    << t.image_refine_ms << " ms, plane hypotheses " << t.plane_ms << " ms\n";
}

}  // namespace mrolr::apps
