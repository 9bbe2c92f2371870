// mrolr-rawlog2bag: a rawlog as a ROS 1 bag.
#include <mrolr/apps/Rawlog2BagApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <ostream>

namespace mrolr::apps
{
void Rawlog2BagApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    "mrolr-rawlog2bag: an MROLR rawlog (a mission's recording or mrolr-sim's) as a ROS 1 bag "
	    "(docs/ros.md)",
	    ' ', "1");
	TCLAP::UnlabeledValueArg<std::string> in("rawlog", "the rawlog to convert", true, "",
	                                         "IN.rawlog", cmd);
	TCLAP::UnlabeledValueArg<std::string> out("bag", "the bag to write (overwritten)", true, "",
	                                          "OUT.bag", cmd);
	TCLAP::SwitchArg js("", "json", "print the messages per topic as JSON", cmd);
	TCLAP::SwitchArg q("", "quiet", "no progress line", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	rawlog_path = in.getValue(), bag_path = out.getValue();
	json = js.getValue(), quiet = q.getValue();
	if (std::filesystem::path(bag_path).extension() != ".bag")
		throw util::UsageError("the output '" + bag_path + "' must end in .bag");
}

int Rawlog2BagApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	if (!std::filesystem::exists(rawlog_path))
		throw std::runtime_error("cannot read rawlog " + rawlog_path + ": no such file");
	std::function<void(size_t, size_t)> show;
	if (!quiet)
		show = [&progress](size_t done, size_t all)
		{
			if (done % 50 == 0 || done == all)
				progress << "\r[rawlog2bag] " << done << " / " << all << " records" << std::flush;
		};
	summary = ros::rawlogToBag(rawlog_path, bag_path, show);
	if (!quiet) progress << "\n";
	if (json)
		out << nlohmann::json{{"bag", bag_path},
		                      {"records", summary.records},
		                      {"pairs", summary.pairs},
		                      {"messages", summary.messages}}
		           .dump(2)
		    << "\n";
	else
	{
		out << bag_path << ": " << summary.records << " records, " << summary.pairs
		    << " stereo pairs\n";
		for (const auto& [topic, n] : summary.messages) out << "  " << topic << ": " << n << "\n";
	}
	return 0;
}

}  // namespace mrolr::apps
