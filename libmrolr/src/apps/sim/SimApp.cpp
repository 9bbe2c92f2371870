#include <mrolr/apps/SimApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <ostream>

namespace mrolr::apps
{
namespace
{
int modeCount(const SimApp& a)
{
	return int(a.snapshot) + int(!a.scene3d_path.empty()) + int(!a.turntable_object.empty()) +
	       int(!a.textures_dir.empty());
}

void checkModes(const SimApp& a)
{
	if (modeCount(a) > 1)
		throw util::UsageError("choose one of --snapshot, --scene3d, --turntable, --make-textures");
	if (a.textures_dir.empty() && a.world_path.empty())
		throw util::UsageError("--world FILE is required");
	const bool needsOut = a.scene3d_path.empty() && a.textures_dir.empty();
	if (needsOut && a.out_path.empty()) throw util::UsageError("--out is required");
}
}  // namespace

std::string SimApp::projectFile(const std::string& relative)
{
	return std::ifstream(relative).good() ? relative
	                                      : std::string(MROLR_SOURCE_DIR) + "/" + relative;
}

void SimApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-sim: the simulated lab (docs/sim.md)", ' ', "1");
	TCLAP::ValueArg<std::string> world("", "world", "world file (maps/<name>/world.ini)", false, "",
	                                   "FILE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "rawlog file, or output folder", false, "", "PATH",
	                                 cmd);
	TCLAP::SwitchArg snap("", "snapshot", "write one stereo pair and truth.json to --out", cmd);
	TCLAP::ValueArg<std::string> pose("", "pose", "snapshot vehicle pose z,x,phi_deg", false,
	                                  "0,0,0", "Z,X,PHI", cmd);
	TCLAP::ValueArg<std::string> head("", "head", "snapshot head angles in degrees", false,
	                                  "0,0,0,0", "PAN,TILT,VL,VR", cmd);
	TCLAP::ValueArg<std::string> scene("", "scene3d", "write the world as a .3Dscene", false, "",
	                                   "FILE", cmd);
	TCLAP::ValueArg<std::string> turn("", "turntable", "object model to put on the turntable",
	                                  false, "", "OBJECT", cmd);
	TCLAP::ValueArg<std::string> tex("", "make-textures", "write the lab's textures to DIR", false,
	                                 "", "DIR", cmd);
	TCLAP::ValueArg<std::string> bis("", "bisight", "head configuration", false,
	                                 "config/bisight.ini", "FILE", cmd);
	TCLAP::ValueArg<std::string> simcfg("", "config", "simulation configuration", false,
	                                    "config/sim.ini", "FILE", cmd);
	TCLAP::ValueArg<int> steps("", "max-steps", "stop recording after N steps (0 = all)", false, 0,
	                           "N", cmd);
	TCLAP::SwitchArg js("", "json", "print the summary as JSON", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	world_path = world.getValue();
	out_path = out.getValue();
	snapshot = snap.getValue();
	pose_zxphi_deg = util::parseNumberList(pose.getValue(), 3, "--pose");
	head_deg = util::parseNumberList(head.getValue(), 4, "--head");
	scene3d_path = scene.getValue();
	turntable_object = turn.getValue();
	textures_dir = tex.getValue();
	bisight_path = projectFile(bis.getValue());
	sim_config_path = projectFile(simcfg.getValue());
	max_steps = steps.getValue();
	if (max_steps < 0) throw util::UsageError("--max-steps must be >= 0");
	json = js.getValue();
	checkModes(*this);
}

int SimApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	const auto t0 = std::chrono::steady_clock::now();
	int rc = 0;
	if (!textures_dir.empty())
		rc = runMakeTextures(out);
	else if (snapshot)
		rc = runSnapshot(out);
	else if (!scene3d_path.empty())
		rc = runScene3d(out);
	else if (!turntable_object.empty())
		rc = runTurntable(out);
	else
		rc = runRecording(out);
	total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	printSummary(out);
	return rc;
}

void SimApp::printSummary(std::ostream& out) const
{
	if (json)
	{
		nlohmann::json j{{"frames", frames_written},
		                 {"render_s", render_s},
		                 {"total_s", total_s},
		                 {"odometry_final_error_m", odometry_final_error_m},
		                 {"files", files_written}};
		out << j.dump(2) << "\n";
		return;
	}
	out << "frames: " << frames_written << "\nrendering: " << render_s << " s\ntotal: " << total_s
	    << " s\n";
	if (odometry_final_error_m > 0)
		out << "odometry final position error: " << odometry_final_error_m << " m\n";
	for (const auto& f : files_written) out << "wrote " << f << "\n";
}

}  // namespace mrolr::apps
