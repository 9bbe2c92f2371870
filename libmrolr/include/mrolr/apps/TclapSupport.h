#pragma once
/** Command-line parsing with MRPT's TCLAP for the model and calibration apps: MRPT's TCLAP prints
 * and swallows errors inside CmdLine::parse, so a throwing output turns them into
 * util::UsageError (exit 2 through util::runMain). Header-only so any app class can use it. */

#include <mrolr/util/Cli.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <string>
#include <vector>

namespace mrolr::apps
{
/** TCLAP output that prints usage normally but throws util::UsageError on a parse failure. */
class ThrowingTclapOutput : public TCLAP::StdOutput
{
   public:
	void failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e) override
	{
		throw util::UsageError(e.argId() + ": " + e.error());
	}
};

/** Parses @p args (argv[0] first) with @p cmd. Returns false when --help or --version was printed
 * (the app should then exit 0); throws util::UsageError for bad arguments. */
inline bool parseTclap(TCLAP::CmdLine& cmd, const std::vector<std::string>& args)
{
	static ThrowingTclapOutput output;
	// CmdLine allocates a default StdOutput and stops owning it once another is set: free it.
	if (cmd.getOutput() != &output) delete cmd.getOutput();
	cmd.setOutput(&output);
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	if (argv.empty()) argv.push_back("mrolr");
	return cmd.parse(static_cast<int>(argv.size()), argv.data());
}

}  // namespace mrolr::apps
