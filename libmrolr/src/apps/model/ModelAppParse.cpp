#include <mrolr/apps/ModelApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

#include <iostream>

namespace mrolr::apps
{
namespace
{
using Str = TCLAP::ValueArg<std::string>;

const char* kUsage =
    "mrolr-model: 3D wire-frame models from stereo (docs/model.md)\n"
    "  build   --turntable DIR --out M.wf [--truth T.wf] [--align turntable|recog] [--json]\n"
    "  scene   --left L.png --right R.png (--calib C.ini | --head pan,tilt,vl,vr) --out S.wf\n"
    "  edit    M.wf [--out M2.wf] [--remove IDS] [--remove-box BOX] [--add-line L] [--add-conic "
    "C]\n"
    "          [--merge] [--grasp x,y,z,yaw,pitch,roll] [--list]\n"
    "  cliques M.wf [--out M2.wf] [--replace] [--json]\n"
    "  show    M.wf --png P.png [--scene3d S.3Dscene] [--azimuth A] [--elevation E]\n"
    "  stats   M.wf [--truth T.wf [--depth D.png [--depth-right DR.png] (--calib C.ini | --head "
    "ANGLES)] [--per-feature]] [--json]\n"
    "'mrolr-model COMMAND --help' lists a command's options.\n";

/** The subcommand's own arguments with "mrolr-model COMMAND" as argv[0]. */
std::vector<std::string> subArgs(const std::vector<std::string>& args)
{
	std::vector<std::string> a{args[0] + " " + args[1]};
	a.insert(a.end(), args.begin() + 2, args.end());
	return a;
}

std::vector<double> numbers(const std::string& text, size_t n, const std::string& what)
{
	return util::parseNumberList(text, n, what);
}

std::vector<int> ids(const std::string& text)
{
	std::vector<int> out;
	for (double v :
	     util::parseNumberList(text, std::count(text.begin(), text.end(), ',') + 1, "--remove"))
	{
		if (v < 1 || v != std::floor(v))
			throw util::UsageError("--remove: ids are positive integers");
		out.push_back(static_cast<int>(v));
	}
	return out;
}
}  // namespace

void ModelApp::initialize(const std::vector<std::string>& args)
{
	if (args.size() < 2 || args[1] == "--help" || args[1] == "-h")
	{
		std::cout << kUsage;
		help_shown = true;
		return;
	}
	command = args[1];
	const auto a = subArgs(args);
	if (command == "build")
		parseBuild(a);
	else if (command == "scene")
		parseScene(a);
	else if (command == "edit")
		parseEdit(a);
	else if (command == "cliques")
		parseCliques(a);
	else if (command == "show")
		parseShow(a);
	else if (command == "stats")
		parseStats(a);
	else
		throw util::UsageError("unknown command '" + command +
		                       "' (build, scene, edit, cliques, show, stats)");
}

void ModelApp::parseBuild(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model build: object model from a turntable directory", ' ', "1");
	Str dir("", "turntable", "turntable directory (turntable.ini)", true, "", "DIR", cmd);
	Str out("", "out", "output .wf", true, "", "M.wf", cmd);
	Str truth("", "truth", "exact model for statistics (default: the directory's)", false, "",
	          "T.wf", cmd);
	Str cfg("", "config", "options", false, config_path, "INI", cmd);
	Str al("", "align",
	       "how views are put together: turntable (the known angles) or recog (each view "
	       "registered to the model so far by recognition, thesis 6.5)",
	       false, align, "METHOD", cmd);
	TCLAP::SwitchArg js("", "json", "JSON summary", cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	turntable_dir = dir.getValue(), out_path = out.getValue(), truth_path = truth.getValue(),
	config_path = cfg.getValue(), json = js.getValue(), align = al.getValue();
	if (align != "turntable" && align != "recog")
		throw util::UsageError("--align: unknown method '" + align + "' (turntable, recog)");
}

void ModelApp::parseScene(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model scene: scene wire-frame from one stereo pair", ' ', "1");
	Str l("", "left", "left image", true, "", "L.png", cmd),
	    r("", "right", "right image", true, "", "R.png", cmd);
	Str calib("", "calib", "stereo calibration .ini (default: the ideal head cameras at --head)",
	          false, "", "C.ini", cmd);
	Str head("", "head", "head angles pan,tilt,vl,vr (deg): output in C0", false, "", "ANGLES",
	         cmd);
	Str bis("", "bisight", "head configuration for --head", false, bisight_path, "INI", cmd);
	Str out("", "out", "output .wf", true, "", "S.wf", cmd);
	Str truth("", "truth", "exact scene model for statistics", false, "", "T.wf", cmd);
	Str cfg("", "config", "options", false, config_path, "INI", cmd);
	TCLAP::SwitchArg js("", "json", "JSON summary", cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	left_png = l.getValue(), right_png = r.getValue(), calib_path = calib.getValue();
	out_path = out.getValue(), truth_path = truth.getValue(), config_path = cfg.getValue();
	bisight_path = bis.getValue(), json = js.getValue();
	if (!head.getValue().empty()) head_deg = numbers(head.getValue(), 4, "--head");
	if (calib_path.empty() && !head_deg) throw util::UsageError("scene needs --calib or --head");
}

void ModelApp::parseEdit(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model edit: the model editor (thesis 6.2)", ' ', "1");
	TCLAP::UnlabeledValueArg<std::string> model("model", "model .wf", true, "", "M.wf", cmd);
	Str out("", "out", "output (default: overwrite the model)", false, "", "M2.wf", cmd);
	Str rm("", "remove", "remove ids (comma-separated)", false, "", "IDS", cmd);
	TCLAP::MultiArg<std::string> box(
	    "", "remove-box", "remove features inside x0,y0,z0,x1,y1,z1 (mm)", false, "BOX", cmd);
	TCLAP::MultiArg<std::string> line("", "add-line", "add x1,y1,z1,x2,y2,z2 (mm)", false, "LINE",
	                                  cmd);
	TCLAP::MultiArg<std::string> conic("", "add-conic", "add cx,cy,cz,nx,ny,nz,ax,ay,az,a,b,t1,t2",
	                                   false, "CONIC", cmd);
	TCLAP::SwitchArg mg("", "merge", "merge duplicated segments", cmd),
	    ls("", "list", "list features", cmd);
	Str gr("", "grasp", "grasp x,y,z (mm),yaw,pitch,roll (deg)", false, "", "GRASP", cmd);
	Str cfg("", "config", "options", false, config_path, "INI", cmd);
	TCLAP::SwitchArg js("", "json", "JSON summary", cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	model_path = model.getValue(), out_path = out.getValue().empty() ? model_path : out.getValue();
	config_path = cfg.getValue(), merge = mg.getValue(), list = ls.getValue(), json = js.getValue();
	if (!rm.getValue().empty()) remove_ids = ids(rm.getValue());
	for (const auto& b : box.getValue()) remove_boxes.push_back(numbers(b, 6, "--remove-box"));
	for (const auto& l : line.getValue()) add_lines.push_back(numbers(l, 6, "--add-line"));
	for (const auto& c : conic.getValue()) add_conics.push_back(numbers(c, 13, "--add-conic"));
	if (!gr.getValue().empty()) grasp = numbers(gr.getValue(), 6, "--grasp");
}

void ModelApp::parseCliques(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model cliques: choose focus features and cliques", ' ', "1");
	TCLAP::UnlabeledValueArg<std::string> model("model", "model .wf", true, "", "M.wf", cmd);
	Str out("", "out", "output (default: overwrite the model)", false, "", "M2.wf", cmd);
	TCLAP::SwitchArg rep("", "replace", "drop the model's own cliques first", cmd);
	Str cfg("", "config", "options", false, config_path, "INI", cmd);
	TCLAP::SwitchArg js("", "json", "JSON summary", cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	model_path = model.getValue(), out_path = out.getValue().empty() ? model_path : out.getValue();
	replace = rep.getValue(), config_path = cfg.getValue(), json = js.getValue();
}

void ModelApp::parseShow(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model show: draw a model", ' ', "1");
	TCLAP::UnlabeledValueArg<std::string> model("model", "model .wf", true, "", "M.wf", cmd);
	Str png("", "png", "PNG drawing", false, "", "P.png", cmd),
	    s3("", "scene3d", ".3Dscene", false, "", "S.3Dscene", cmd);
	Str az("", "azimuth", "view azimuth (deg)", false, "", "A", cmd),
	    el("", "elevation", "view elevation (deg)", false, "", "E", cmd);
	TCLAP::SwitchArg js("", "json", "JSON summary", cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	model_path = model.getValue(), png_path = png.getValue(), scene3d_path = s3.getValue();
	json = js.getValue();
	if (png_path.empty() && scene3d_path.empty())
		throw util::UsageError("show needs --png and/or --scene3d");
	if (!az.getValue().empty()) azimuth_deg = util::parseNumberArg(az.getValue(), "--azimuth");
	if (!el.getValue().empty()) elevation_deg = util::parseNumberArg(el.getValue(), "--elevation");
}

void ModelApp::parseStats(const std::vector<std::string>& a)
{
	TCLAP::CmdLine cmd("mrolr-model stats: model statistics, optionally against the truth", ' ',
	                   "1");
	TCLAP::UnlabeledValueArg<std::string> model("model", "model .wf", true, "", "M.wf", cmd);
	Str truth("", "truth", "exact model", false, "", "T.wf", cmd);
	Str depth("", "depth",
	          "left depth image (16-bit mm): compare with the visible part of the truth only "
	          "(both models in left_camera; needs --calib or --head)",
	          false, "", "D.png", cmd);
	Str depth_r("", "depth-right",
	            "right depth image (16-bit mm, with --depth): the part of the truth BOTH cameras "
	            "see, all a stereo pair can reconstruct",
	            false, "", "D.png", cmd);
	Str calib("", "calib", "stereo calibration of the view (with --depth)", false, "", "C.ini",
	          cmd);
	Str head("", "head", "head angles pan,tilt,vl,vr (deg) of the view: the ideal head cameras",
	         false, "", "ANGLES", cmd);
	Str bis("", "bisight", "head configuration for --head", false, bisight_path, "INI", cmd);
	Str cfg("", "config", "options", false, config_path, "INI", cmd);
	TCLAP::SwitchArg js("", "json", "JSON output", cmd);
	TCLAP::SwitchArg pf("", "per-feature",
	                    "with --truth: every (visible) true feature with its length, recovered "
	                    "length, middle point and, for a line, its angle to the image rows",
	                    cmd);
	if ((help_shown = !parseTclap(cmd, a))) return;
	model_path = model.getValue(), truth_path = truth.getValue(), config_path = cfg.getValue();
	per_feature = pf.getValue();
	depth_png = depth.getValue(), calib_path = calib.getValue(), bisight_path = bis.getValue();
	depth_right_png = depth_r.getValue();
	json = js.getValue();
	if (!head.getValue().empty()) head_deg = numbers(head.getValue(), 4, "--head");
	if (!depth_png.empty() && (truth_path.empty() || (calib_path.empty() && !head_deg)))
		throw util::UsageError("stats --depth needs --truth and --calib or --head");
	if (!depth_right_png.empty() && depth_png.empty())
		throw util::UsageError("stats --depth-right needs --depth (the left depth image)");
}

}  // namespace mrolr::apps
