#pragma once
/** `mrolr-recognize`: recognise object models in scene wire-frames and report their poses (thesis
 * 6.3–6.4).
 *
 *     mrolr-recognize --model M.wf [--model M2.wf ...]
 *                     (--scene S.wf [--scene S2.wf ...] | --left L.png --right R.png --calib C.ini)
 *                     [--config config/recognition.ini] [--scene-config config/model.ini]
 *                     [--overlay OUT.png] [--scene3d OUT.3Dscene] [--json]
 *
 * Several --scene files are the scene models of a pan sweep, searched in order (the first scene
 * that recognises a model ends that model's search). With --left/--right/--calib the scene is built
 * from the stereo pair by stereo::reconstructScene ([scene] of --scene-config). --overlay draws the
 * scene and the recognised models on the left image projected with the calibration's left camera
 * (needs --calib; without --left it draws on a blank canvas of the calibration's image size).
 *
 *     mrolr-recognize --make-demo DIR
 *
 * writes the ten synthetic lab objects (DIR/models/NAME.wf) and noisy, cluttered table scenes with
 * their truth (DIR/scenes/table_K.wf, DIR/scenes/truth.json) for trying the tool.
 *
 *     mrolr-recognize --evaluate DIR [--model M.wf ... | --truth-models] [--eval-scenes N]
 *                     [--eval-seed S] [--config config/recognition.ini] [--no-image-verify]
 *                     [--json]
 *
 * renders the fixed evaluation set of [evaluation], reconstructs every scene, searches every model
 * (default every .wf of datasets/objects; --truth-models: the simulator's exact wire-frames) and
 * compares with the truth (eval::evaluateSet, eval/RecognitionEvaluation.h); the app writes
 * DIR/scene_KK/{left,right,overlay}.png, scene.wf, calib.ini, truth.json, and DIR/cases.json,
 * DIR/summary.json.
 *
 * With a stereo pair (--left/--right/--calib and --evaluate) the hypotheses are verified in the
 * images (recog::ImageVerifier, [image_verification] of --config) unless --no-image-verify. */

#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
class RecognizeApp
{
 public:
	/** Parses the arguments (argv[0] first); throws util::UsageError for bad or missing ones. */
	void initialize(const std::vector<std::string>& args);

	/** Loads models, options and scenes, recognises every model, prints the results (text or one
	 * JSON object) and writes the overlay / 3D scene. Returns the exit code (0 also when objects
	 * are not found: "not found" is an answer). */
	int run(std::ostream& out);

	// Inputs (set by initialize)
	std::vector<std::string> model_paths, scene_paths;
	std::string left_png, right_png, calib_path;
	std::string config_path = "config/recognition.ini";
	std::string scene_config_path = "config/model.ini";
	std::string overlay_png, scene3d_path;
	std::string judgement_prefix;  ///< --judgement: PREFIX_<model>.png per found model
	std::string demo_dir;          ///< --make-demo
	std::string evaluate_dir;      ///< --evaluate
	bool truth_models = false;     ///< --truth-models
	int eval_scenes = 0;           ///< --eval-scenes (0: [evaluation] scenes)
	long eval_seed = -1;           ///< --eval-seed (-1: [evaluation] seed)
	/** Verify hypotheses in the stereo images when there are images (false: --no-image-verify). */
	bool image_verify = true;
	/** --support-plane nx,ny,nz,d_mm (--left/--right form): the table top in the scene frame L,
	 * points x with n·x + d = 0 (n up, normalised here); unset without the option. */
	std::optional<recog::SupportPlane> support_plane;
	/** Hypotheses from single features on the support plane ([plane_hypotheses] enable; false:
	 * --no-plane-hypotheses). */
	bool plane_hypotheses = true;
	bool json = false;
	bool help_shown = false;

	// Results (set by run)
	recog::RecognitionOptions options;
	recog::ImageVerificationOptions image_options;  ///< [image_verification], read when used
	std::vector<model::WireFrame> models;
	std::vector<model::WireFrame> scenes;           ///< the scene models searched, in order
	std::vector<recog::RecognitionResult> results;  ///< one per model, in --model order
	eval::EvaluationOptions eval_options;           ///< --evaluate
	std::vector<eval::EvalCase> eval_cases;
	eval::EvalSummary eval_summary;

 private:
	void loadScenes();
	/** options from [recognition] and [plane_hypotheses] of config_path (and plane_hypotheses). */
	void loadRecognitionOptions();
	/** The single stereo scene searched with verification in @p images; @p repeat: @p rec
	 * searched it last (recog::SceneContext::repeat). */
	recog::RecognitionResult recognizeInImages(const recog::Recognizer& rec,
	                                           const recog::ImageVerifier& images,
	                                           bool repeat = false) const;
	int runEvaluation(std::ostream& out);
	/** Mutual occlusion for mrolr-recognize --left/--right: each model of @p recs (same order as
	 * results) not found is searched again with the found ones as occluders. */
	void searchBehindFound(const std::vector<recog::Recognizer>& recs,
	                       const recog::ImageVerifier& images);
	/** --judgement: the left image with the judged samples of each found model of @p recs. */
	void writeJudgements(const std::vector<recog::Recognizer>& recs,
	                     const recog::ImageVerifier& images) const;
	/** --evaluate: DIR/scene_KK/ of scene @p s and its overlay of what was @p found. */
	void writeEvaluationScene(const eval::EvalScene& s,
	                          const std::vector<recog::RecognitionResult>& found) const;
	void writeEvaluation(std::ostream& out) const;
	void writeDemo(std::ostream& out) const;
	void printText(std::ostream& out) const;
	void printJson(std::ostream& out) const;
};

}  // namespace mrolr::apps
