#include <mrolr/apps/SlamApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Config.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <ostream>

namespace mrolr::apps
{
void SlamApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-slam: vision-driven EKF-SLAM on a simulated world", ' ', "1");
	TCLAP::ValueArg<std::string> world(
	    "", "world", "world file (maps/<name>/world.ini); optional with --rawlog (true landmarks)",
	    false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> config("", "config", "SLAM configuration", false,
	                                    std::string(MROLR_SOURCE_DIR) + "/config/slam.ini", "FILE",
	                                    cmd);
	TCLAP::SwitchArg liveArg(
	    "", "live", "run on the simulator: drive the waypoints, measure with the head", cmd);
	TCLAP::ValueArg<std::string> headArg(
	    "", "head", "lab (the rendered lab, sim::SimHead; default) or synthetic (textured points)",
	    false, "lab", "KIND", cmd);
	TCLAP::ValueArg<std::string> knownArg(
	    "", "known",
	    "landmarks to acquire as known features at the start (--acquire-known, or --live without "
	    "<world dir>/known_features.ini); comma-separated names, default: the world's known",
	    false,
	    "", "NAMES", cmd);
	TCLAP::SwitchArg acquireArg("", "acquire-known",
	                            "fixate the world's known landmarks from the first waypoint and "
	                            "write <world dir>/known_features.ini",
	                            cmd);
	TCLAP::ValueArg<std::string> rawlog(
	    "", "rawlog",
	    "replay a rawlog recorded by mrolr-sim (recorded odometry, stereo pairs and head angles)",
	    false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> out(
	    "", "out",
	    "folder for trajectory/map/decisions CSV, paths.png, truth/estimate/odometry.tum, decisions.rawlog and slam.3Dscene",
	    false, "", "DIR", cmd);
	TCLAP::SwitchArg js("", "json", "print the summary as JSON", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	world_path = world.getValue(), config_path = config.getValue(), rawlog_path = rawlog.getValue();
	out_dir = out.getValue(), live = liveArg.getValue(), json = js.getValue();
	acquire_known = acquireArg.getValue();
	head_kind = headArg.getValue();
	if (head_kind != "synthetic" && head_kind != "lab")
		throw util::UsageError("--head: '" + head_kind + "' is neither synthetic nor lab");
	known_names = util::splitFields(knownArg.getValue());
	if (int(live) + int(acquire_known) + int(!rawlog_path.empty()) != 1)
		throw util::UsageError("give exactly one of --live, --acquire-known and --rawlog FILE");
	if (!rawlog_path.empty() && headArg.isSet())
		throw util::UsageError("--head applies to --live and --acquire-known, not to --rawlog");
	if (rawlog_path.empty() && world_path.empty())
		throw util::UsageError("--live and --acquire-known need --world FILE");
}

namespace
{
double planarError(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	return (a - b).head<2>().norm();
}

SlamSummary summarise(const std::vector<SlamStepLog>& steps, SlamSummary s)
{
	double se_slam = 0, se_dr = 0;
	for (const auto& st : steps)
	{
		se_slam += std::pow(planarError(st.x_est, st.x_true), 2);
		se_dr += std::pow(planarError(st.x_dr, st.x_true), 2);
		for (const auto& r : st.records)
		{
			s.measurements += r.measured;
			s.matched += r.measurement.found;
			s.accepted += r.accepted;
			s.mean_times += r.times;
			s.saccades += r.saccade;
			s.measurements_lost_to_saccades += r.measurements_lost;
		}
	}
	const double n = std::max<size_t>(steps.size(), 1);
	s.cycles = static_cast<int>(steps.size());
	s.slam_rms_position_m = std::sqrt(se_slam / n), s.dr_rms_position_m = std::sqrt(se_dr / n);
	if (!steps.empty())
	{
		s.slam_final_position_error_m = planarError(steps.back().x_est, steps.back().x_true);
		s.dr_final_position_error_m = planarError(steps.back().x_dr, steps.back().x_true);
	}
	s.match_success_rate = s.measurements ? double(s.accepted) / s.measurements : 0;
	auto& t = s.mean_times;
	for (double* v : {&t.predict_ms, &t.manage_ms, &t.select_ms, &t.search_ms, &t.grab_ms,
	                  &t.match_ms, &t.update_ms})
		*v /= n;
	return s;
}

nlohmann::json toJson(const SlamSummary& s)
{
	const auto& t = s.mean_times;
	return {{"slam_final_position_error_m", s.slam_final_position_error_m},
	        {"slam_rms_position_m", s.slam_rms_position_m},
	        {"dr_final_position_error_m", s.dr_final_position_error_m},
	        {"dr_rms_position_m", s.dr_rms_position_m},
	        {"features", s.features},
	        {"features_added", s.features_added},
	        {"features_deleted", s.features_deleted},
	        {"measurements", s.measurements},
	        {"matched", s.matched},
	        {"accepted", s.accepted},
	        {"match_success_rate", s.match_success_rate},
	        {"cycles", s.cycles},
	        {"selection", s.selection},
	        {"saccades", s.saccades},
	        {"measurements_lost_to_saccades", s.measurements_lost_to_saccades},
	        {"ms_per_cycle",
	         {{"processing", t.processingMs()},
	          {"predict", t.predict_ms},
	          {"select", t.select_ms},
	          {"search", t.search_ms},
	          {"match", t.match_ms},
	          {"update", t.update_ms},
	          {"grab_images", t.grab_ms},
	          {"acquire_features", t.manage_ms}}}};
}
}  // namespace

int SlamApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	if (acquire_known)
	{
		runAcquireKnown(out);
		return util::kExitOk;
	}
	steps.clear(), true_landmarks.clear();
	summary = SlamSummary();
	if (live)
		runLive();
	else
		runReplay();
	summary = summarise(steps, summary);
	if (!out_dir.empty()) writeOutputs();
	printSummary(out);
	return util::kExitOk;
}

void SlamApp::recordMap(slam::ActiveSlamFilter& filter, const vision::VisualSlam& vslam)
{
	summary.features_added = vslam.featuresAdded();
	summary.features_deleted = vslam.featuresDeleted();
	summary.features = static_cast<int>(filter.numFeatures());
	map.clear();
	for (size_t i = 0; i < filter.numFeatures(); ++i)
		map.push_back({filter.info(i).label, filter.info(i).known, filter.feature(i),
		               filter.featureCovariance(i)});
}

void SlamApp::printSummary(std::ostream& out) const
{
	const nlohmann::json j = toJson(summary);
	if (json)
	{
		out << j.dump(2) << "\n";
		return;
	}
	out << std::setprecision(4);
	for (const auto& [key, value] : j.items())
		if (!value.is_object()) out << std::left << std::setw(30) << key << value << "\n";
	for (const auto& [key, value] : j["ms_per_cycle"].items())
		out << "ms_per_cycle." << std::left << std::setw(17) << key << value << "\n";
}

}  // namespace mrolr::apps
