#include <mrolr/apps/EvalApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/eval/MissionEval.h>
#include <mrolr/mission/MissionOutputs.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace mrolr::apps
{
namespace
{
using nlohmann::json;

json readJson(const std::string& path, const std::string& what)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error(what + " '" + path + "': cannot open");
	try
	{
		return json::parse(in);
	}
	catch (const json::exception& e)
	{
		throw std::runtime_error(what + " '" + path + "': not JSON: " + e.what());
	}
}

std::string num(const json& v)
{
	if (!v.is_number()) return "n/a";
	std::ostringstream s;
	s << std::fixed << std::setprecision(3) << v.get<double>();
	return s.str();
}
}  // namespace

void EvalApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-eval: a run's report checked against the world's truth", ' ', "1");
	TCLAP::ValueArg<std::string> rep("", "report", "report.json of the run", true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> tru("", "truth", "T.json of mrolr-serial emulate --truth-out",
	                                 true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "where to write (default: the report itself)",
	                                 false, "", "FILE", cmd);
	TCLAP::SwitchArg js("", "json", "print the evaluated report", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	report_path = rep.getValue(), truth_path = tru.getValue(), out_path = out.getValue();
	json = js.getValue();
}

int EvalApp::run(std::ostream& out)
{
	if (help_shown) return 0;
	report = readJson(report_path, "report");
	const auto truth = eval::truthFromJson(readJson(truth_path, "truth"), truth_path);
	try
	{
		eval::evaluateMission(report, truth);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(report_path + ": " + e.what());
	}
	const std::string target = out_path.empty() ? report_path : out_path;
	std::ofstream(target) << report.dump(2) << "\n";
	std::ofstream((std::filesystem::path(target).parent_path() / "report.md").string())
	    << mission::reportMarkdown(report);
	if (json)
		out << report.dump(2) << "\n";
	else
		out << "eval " << (report["success"].get<bool>() ? "CONFIRMS" : "DOES NOT CONFIRM")
		    << " the robot's success\n  home error " << num(report["final_position_error_m"])
		    << " m (the robot's estimate " << num(report["robot"]["home_estimate_error_m"])
		    << " m), object "
		    << (report["eval"]["object_on_board"].get<bool>() ? "on the deck"
		        : report["eval"]["object_held"].get<bool>() ? "in the gripper"
		                                                    : "not retrieved")
		    << ", object pose error " << num(report["object_translation_error_mm"]) << " mm\n"
		    << "  written to " << target << "\n";
	return report["success"].get<bool>() ? 0 : 3;
}

}  // namespace mrolr::apps
