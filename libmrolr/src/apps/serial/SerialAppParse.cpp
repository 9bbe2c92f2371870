#include <mrolr/apps/SerialApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

namespace mrolr::apps
{
namespace
{
void checkRanges(const SerialApp& a)
{
	if (a.seconds < 0) throw util::UsageError("--seconds must not be negative");
	if (a.faults.reply_delay_ms < 0) throw util::UsageError("--delay-ms must not be negative");
	if (a.faults.drop_byte_probability < 0 || a.faults.drop_byte_probability >= 1)
		throw util::UsageError("--drop-probability must be in [0, 1)");
	if (a.timeout_ms <= 0) throw util::UsageError("--timeout-ms must be positive");
	if (a.retries < 0) throw util::UsageError("--retries must not be negative");
}

void takePositionals(SerialApp& a, const std::vector<std::string>& rest)
{
	if (a.command == "emulate")
	{
		if (!rest.empty()) throw util::UsageError("emulate takes no positional arguments");
		return;
	}
	if (rest.size() < 2)
		throw util::UsageError("send needs PORT and VERB (e.g. send /dev/pts/3 ODO?)");
	a.port = rest[0];
	a.verb = rest[1];
	for (size_t i = 2; i < rest.size(); ++i)
		a.fields.push_back(rest[i].empty() || rest[i][0] != ' ' ? rest[i] : rest[i].substr(1));
}
}  // namespace

void SerialApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    "mrolr-serial: device emulators on pseudo-terminals and a one-shot "
	    "request to a serial device (docs/serial.md)",
	    ' ', "1.0");
	std::vector<std::string> mode_names{"emulate", "send"};
	TCLAP::ValuesConstraint<std::string> modes(mode_names);
	TCLAP::UnlabeledValueArg<std::string> mode("command", "emulate | send", true, "", &modes, cmd);
	TCLAP::UnlabeledMultiArg<std::string> rest("args", "send: PORT VERB [FIELD...]", false, "ARG",
	                                           cmd);
	TCLAP::SwitchArg json_arg("", "json", "print the result as JSON", cmd);
	TCLAP::ValueArg<double> sec("", "seconds", "emulate: run time (0 = until Ctrl-C)", false, 0,
	                            "S", cmd);
	TCLAP::ValueArg<int> delay("", "delay-ms", "emulate: reply delay", false, 0, "N", cmd);
	TCLAP::ValueArg<double> drop("", "drop-probability", "emulate: chance to lose each reply byte",
	                             false, 0, "P", cmd);
	TCLAP::ValueArg<std::string> sim(
	    "", "sim", "emulate: mission file whose simulator sections build the lab", false,
	    MROLR_SOURCE_DIR "/config/mission_sim.ini", "FILE", cmd);
	TCLAP::ValueArg<std::string> world("", "world",
	                                   "emulate: the world (default [simulator] world_file)", false,
	                                   "", "W.ini", cmd);
	TCLAP::ValueArg<std::string> truth("", "truth-out",
	                                   "emulate: write the truth here at the end (T.json)", false,
	                                   "", "FILE", cmd);
	TCLAP::ValueArg<int> baud_arg("", "baud", "send: line speed", false, 9600, "B", cmd);
	TCLAP::ValueArg<int> tmo("", "timeout-ms", "send: reply timeout per attempt", false, 500, "T",
	                         cmd);
	TCLAP::ValueArg<int> rtr("", "retries", "send: resends after the first attempt", false, 3, "R",
	                         cmd);
	try
	{
		if (!parseTclap(cmd, args))
		{
			help_shown = true;
			return;
		}
	}
	catch (const TCLAP::ArgException& e)
	{
		throw util::UsageError(e.argId() + ": " + e.error());
	}
	command = mode.getValue(), json = json_arg.getValue(), seconds = sec.getValue();
	faults.reply_delay_ms = delay.getValue(), faults.drop_byte_probability = drop.getValue();
	sim_file = sim.getValue(), world_file = world.getValue(), truth_out = truth.getValue();
	baud = baud_arg.getValue(), timeout_ms = tmo.getValue(), retries = rtr.getValue();
	takePositionals(*this, rest.getValue());
	checkRanges(*this);
}

}  // namespace mrolr::apps
