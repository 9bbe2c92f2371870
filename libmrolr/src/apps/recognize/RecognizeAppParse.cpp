#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

namespace mrolr::apps
{
namespace
{
recog::SupportPlane parseSupportPlane(const std::string& text)
{
	const auto v = util::parseNumberList(text, 4, "--support-plane nx,ny,nz,d_mm");
	try
	{
		return recog::SupportPlane::fromCoefficients(Eigen::Vector3d(v[0], v[1], v[2]), v[3]);
	}
	catch (const std::invalid_argument& e)
	{
		throw util::UsageError(std::string("--support-plane: ") + e.what());
	}
}

void requireInputs(const RecognizeApp& a)
{
	const bool stereo = !a.left_png.empty() || !a.right_png.empty();
	if (a.scene_paths.empty() && !stereo)
		throw util::UsageError("give the scene: --scene S.wf, or --left, --right and --calib");
	if (!a.scene_paths.empty() && !a.right_png.empty())
		throw util::UsageError("--scene and --right exclude each other (one source of scene)");
	if (stereo && a.scene_paths.empty() &&
	    (a.left_png.empty() || a.right_png.empty() || a.calib_path.empty()))
		throw util::UsageError("building the scene from stereo needs --left, --right and --calib");
	if (a.support_plane && a.right_png.empty())
		throw util::UsageError("--support-plane is for a stereo scene (--left/--right/--calib)");
	if (!a.judgement_prefix.empty() && (a.right_png.empty() || !a.image_verify))
		throw util::UsageError(
		    "--judgement draws the image verification: it needs --left/--right/--calib and no "
		    "--no-image-verify");
	if (!a.overlay_png.empty() && a.calib_path.empty())
		throw util::UsageError("--overlay projects with the left camera: it needs --calib");
}
}  // namespace

void RecognizeApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("Recognise wire-frame object models in a scene and report their poses", ' ',
	                   "0.1");
	using Str = TCLAP::ValueArg<std::string>;
	TCLAP::MultiArg<std::string> model("", "model", "object model .wf (repeatable)", false, "M.wf",
	                                   cmd);
	TCLAP::MultiArg<std::string> scene("", "scene",
	                                   "scene model .wf; several = a pan sweep searched in order",
	                                   false, "S.wf", cmd);
	Str left("", "left", "left image (stereo scene and overlay)", false, "", "L.png", cmd);
	Str right("", "right", "right image (stereo scene)", false, "", "R.png", cmd);
	Str calib("", "calib", "stereo calibration .ini ([stereo_calib])", false, "", "C.ini", cmd);
	Str cfg("", "config", "recognition options", false, config_path, "INI", cmd);
	Str scfg("", "scene-config", "scene building options ([scene])", false, scene_config_path,
	         "INI", cmd);
	Str overlay("", "overlay", "PNG of the models drawn on the left image", false, "", "OUT.png",
	            cmd);
	Str judgement("", "judgement",
	              "--left/--right with image verification: for each found model, "
	              "PREFIX_<model>.png of the left image with its judged edge samples (supported "
	              "green, unsupported red, hidden blue; crosses: silhouette lines)",
	              false, "", "PREFIX", cmd);
	Str s3d("", "scene3d", "MRPT .3Dscene of scene and recognised models", false, "", "OUT.3Dscene",
	        cmd);
	TCLAP::SwitchArg js("", "json", "print one JSON object", cmd);
	Str demo("", "make-demo", "write demo models and scenes into DIR and exit", false, "", "DIR",
	         cmd);
	Str evaluate("", "evaluate",
	             "render the evaluation set ([evaluation] of --config), recognise, compare with "
	             "the truth; outputs into DIR",
	             false, "", "DIR", cmd);
	TCLAP::SwitchArg truth("", "truth-models",
	                       "--evaluate with the simulator's exact wire-frames as the models", cmd);
	TCLAP::ValueArg<int> nscenes("", "eval-scenes", "--evaluate: number of scenes", false, 0, "N",
	                             cmd);
	TCLAP::ValueArg<long> seed("", "eval-seed", "--evaluate: seed of scene 0", false, -1, "S", cmd);
	TCLAP::SwitchArg no_images("", "no-image-verify",
	                           "with a stereo pair (--left/--right, --evaluate): verify in 3D "
	                           "only, not in the images ([image_verification] of --config)",
	                           cmd);
	Str plane("", "support-plane",
	          "--left/--right: the plane the objects stand on, in the left camera frame L: "
	          "normal (pointing up) and offset, points x with nx*x + ny*y + nz*z + d_mm = 0 (mm); "
	          "gives the upright prior and the single-feature hypotheses on the plane "
	          "([plane_hypotheses] of --config)",
	          false, "", "nx,ny,nz,d_mm", cmd);
	TCLAP::SwitchArg no_plane("", "no-plane-hypotheses",
	                          "no single-feature hypotheses on the support plane (--evaluate, "
	                          "--support-plane)",
	                          cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	model_paths = model.getValue(), scene_paths = scene.getValue();
	left_png = left.getValue(), right_png = right.getValue(), calib_path = calib.getValue();
	config_path = cfg.getValue(), scene_config_path = scfg.getValue();
	overlay_png = overlay.getValue(), scene3d_path = s3d.getValue(), json = js.getValue();
	judgement_prefix = judgement.getValue();
	demo_dir = demo.getValue();
	evaluate_dir = evaluate.getValue(), truth_models = truth.getValue();
	eval_scenes = nscenes.getValue(), eval_seed = seed.getValue();
	image_verify = !no_images.getValue();
	plane_hypotheses = !no_plane.getValue();
	if (!plane.getValue().empty()) support_plane = parseSupportPlane(plane.getValue());
	if (eval_scenes < 0) throw util::UsageError("--eval-scenes must be positive");
	if (!demo_dir.empty()) return;
	if (!evaluate_dir.empty())
	{
		if (!scene_paths.empty() || !left_png.empty() || !right_png.empty())
			throw util::UsageError("--evaluate renders its own scenes: no --scene/--left/--right");
		return;
	}
	if (model_paths.empty()) throw util::UsageError("give at least one --model M.wf");
	requireInputs(*this);
}

}  // namespace mrolr::apps
