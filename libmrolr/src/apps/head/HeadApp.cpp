#include <mrolr/apps/HeadApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>

namespace mrolr::apps
{
namespace
{
struct CommandSpec
{
	std::vector<std::string> inputs, outputs;
};

const std::map<std::string, CommandSpec>& commands()
{
	static const std::map<std::string, CommandSpec> specs = {
	    {"fixate", {{"X", "Y", "Z"}, {"pan", "tilt", "verg_left", "verg_right"}}},
	    {"project", {{"X", "Y", "Z", "PAN", "TILT", "VL", "VR"}, {"uL", "vL", "uR", "vR"}}},
	    {"triangulate", {{"UL", "VL", "UR", "VR", "PAN", "TILT", "VL", "VR"}, {"X", "Y", "Z"}}},
	    {"measure", {{"X", "Y", "Z"}, {"pan", "elevation", "vergence"}}},
	};
	return specs;
}

const char* kUsage =
    "commands (points in metres in C0: x left, y up, z forward; angles in radians):\n"
    "  fixate X Y Z                            -> pan tilt verg_left verg_right\n"
    "  project X Y Z PAN TILT VL VR            -> uL vL uR vR\n"
    "  triangulate UL VL UR VR PAN TILT VL VR  -> X Y Z (and cov in --json)\n"
    "  measure X Y Z                           -> pan elevation vergence (ideal head, eq 5.40)";

std::string joined(const std::vector<std::string>& v)
{
	std::string s;
	for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
	return s;
}

std::vector<double> parseInputs(const std::string& cmd, const std::vector<std::string>& args)
{
	const auto it = commands().find(cmd);
	if (it == commands().end()) throw util::UsageError("unknown command '" + cmd + "'\n" + kUsage);
	const auto& names = it->second.inputs;
	if (args.size() != names.size())
		throw util::UsageError(cmd + " takes " + std::to_string(names.size()) + " numbers (" +
		                       joined(names) + "), got " + std::to_string(args.size()));
	std::vector<double> out;
	for (size_t i = 0; i < args.size(); ++i)
		out.push_back(util::parseNumberArg(args[i], cmd + " " + names[i]));
	return out;
}

geometry::HeadAngles anglesAt(const std::vector<double>& v, size_t first)
{
	return {v[first], v[first + 1], v[first + 2], v[first + 3]};
}
}  // namespace

std::string HeadApp::defaultConfigPath()
{
	return util::projectFile("config/bisight.ini");
}

void HeadApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(std::string("mrolr-head: BiSight head geometry (thesis 4.2).\n") + kUsage,
	                   ' ', "1");
	TCLAP::ValueArg<std::string> cfg("", "config", "head .ini ([bisight])", false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> sigma("", "sigma-px",
	                                   "pixel noise for triangulate's covariance (default 1)",
	                                   false, "1", "S", cmd);
	TCLAP::SwitchArg js("", "json", "print one JSON object keyed by the output names", cmd);
	TCLAP::UnlabeledValueArg<std::string> command_arg(
	    "command", "fixate | project | triangulate | measure", true, "", "COMMAND", cmd);
	TCLAP::UnlabeledMultiArg<std::string> rest("numbers", "the command's numbers", false, "N", cmd);
	help_shown = !parseTclap(cmd, args);
	if (help_shown) return;
	config_path = cfg.getValue();
	json = js.getValue();
	sigma_px = util::parseNumberArg(sigma.getValue(), "--sigma-px");
	if (sigma_px < 0) throw util::UsageError("--sigma-px must be >= 0");
	command = command_arg.getValue();
	numbers = parseInputs(command, rest.getValue());
}

int HeadApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	options =
	    geometry::BiSightOptions::fromFile(config_path.empty() ? defaultConfigPath() : config_path);
	const geometry::BiSightHead head(options);
	const Eigen::Vector3d p(numbers[0], numbers[1], numbers[2]);
	output_names = commands().at(command).outputs;
	if (command == "fixate")
	{
		const geometry::HeadAngles a = head.fixate(p);
		output_values = {a.pan, a.tilt, a.verg_left, a.verg_right};
	}
	else if (command == "project")
	{
		const Eigen::Vector4d px = head.project(p, anglesAt(numbers, 3)).asVector();
		output_values.assign(px.data(), px.data() + 4);
	}
	else if (command == "triangulate")
	{
		const geometry::StereoPixels px{numbers[0], numbers[1], numbers[2], numbers[3]};
		const geometry::Triangulation t = head.triangulate(px, anglesAt(numbers, 4), sigma_px);
		output_values.assign(t.p_GinC0.data(), t.p_GinC0.data() + 3);
		cov = t.cov;
	}
	else
	{
		const Eigen::Vector3d h = geometry::idealHeadMeasure(p, options.interocular_m);
		output_values.assign(h.data(), h.data() + 3);
	}
	print(out);
	return util::kExitOk;
}

void HeadApp::print(std::ostream& out) const
{
	if (!json)
	{
		out << std::setprecision(15);
		for (size_t i = 0; i < output_values.size(); ++i) out << (i ? " " : "") << output_values[i];
		out << "\n";
		return;
	}
	nlohmann::json j = nlohmann::json::object();
	for (size_t i = 0; i < output_values.size(); ++i) j[output_names[i]] = output_values[i];
	if (cov)
		for (int r = 0; r < 3; ++r) j["cov"].push_back({(*cov)(r, 0), (*cov)(r, 1), (*cov)(r, 2)});
	out << j.dump() << "\n";
}

}  // namespace mrolr::apps
