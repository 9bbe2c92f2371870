#include <mrolr/hw_serial/DeviceProtocols.h>
#include <mrolr/hw_serial/Message.h>

namespace mrolr::hw_serial
{
namespace
{
void requireNoArgs(const std::vector<std::string>& args, const std::string& verb)
{
	if (!args.empty())
		throw CommandError(errcode::kBadArg,
		                   verb + " takes no arguments, got " + std::to_string(args.size()));
}

std::vector<std::string> identify(const char* id, const std::vector<std::string>& args)
{
	requireNoArgs(args, "ID?");
	return {id, "1"};
}

[[noreturn]] void unknown(const std::string& verb, const char* id)
{
	throw CommandError(errcode::kBadCmd, "unknown command '" + verb + "' for " + id);
}
}  // namespace

std::vector<std::string> numberFields(const std::vector<double>& values)
{
	std::vector<std::string> out;
	for (double v : values) out.push_back(formatNumber(v));
	return out;
}

std::vector<double> requireNumbers(const std::vector<std::string>& args, size_t count,
                                   const std::string& verb)
{
	try
	{
		return parseNumbers(args, count, verb);
	}
	catch (const std::invalid_argument& e)
	{
		throw CommandError(errcode::kBadArg, e.what());
	}
}

std::vector<std::string> BaseHandler::execute(const std::string& verb,
                                              const std::vector<std::string>& args)
{
	if (verb == "ID?") return identify(kBaseId, args);
	if (verb == "STEP")
	{
		const auto v = requireNumbers(args, 3, verb);
		if (v[2] < 0) throw CommandError(errcode::kBadArg, "STEP: dt_s must not be negative");
		device_.step(base::WheelControl{v[0], v[1], v[2]});
		return {};
	}
	if (verb != "ODO?") unknown(verb, kBaseId);
	requireNoArgs(args, verb);
	const hw::Odometry o = device_.odometry();
	auto fields = numberFields({o.xv_zxphi[0], o.xv_zxphi[1], o.xv_zxphi[2]});
	fields.push_back(std::to_string(o.ticks_right));
	fields.push_back(std::to_string(o.ticks_left));
	fields.push_back(formatNumber(o.time_s));
	fields.push_back(o.bumper ? "1" : "0");
	return fields;
}

std::vector<std::string> HeadHandler::execute(const std::string& verb,
                                              const std::vector<std::string>& args)
{
	if (verb == "ID?") return identify(kHeadId, args);
	if (verb == "MOVE")
	{
		const auto v = requireNumbers(args, 4, verb);
		return numberFields({device_.moveTo(geometry::HeadAngles{v[0], v[1], v[2], v[3]})});
	}
	if (verb != "ANG?") unknown(verb, kHeadId);
	requireNoArgs(args, verb);
	const auto a = device_.angles();
	return numberFields({a.pan, a.tilt, a.verg_left, a.verg_right});
}

std::vector<std::string> ArmHandler::execute(const std::string& verb,
                                             const std::vector<std::string>& args)
{
	if (verb == "ID?") return identify(kArmId, args);
	if (verb == "MOVE")
	{
		const auto v = requireNumbers(args, 7, verb);
		hw::ArmJoints j;
		std::copy(v.begin(), v.end(), j.begin());
		device_.moveTo(j);
		return {};
	}
	if (verb == "GRIP")
	{
		if (args.size() != 1 || (args[0] != "0" && args[0] != "1"))
			throw CommandError(errcode::kBadArg, "GRIP takes one field, 0 (open) or 1 (close)");
		device_.setGripper(args[0] == "1");
		return {};
	}
	if (verb == "DOCK")
	{
		if (args.size() != 1 || (args[0] != "0" && args[0] != "1"))
			throw CommandError(errcode::kBadArg, "DOCK takes one field, 0 (de-couple) or 1 (dock)");
		device_.dock(args[0] == "1");
		return {};
	}
	if (verb != "GRIP?" && verb != "JNT?" && verb != "DOCK?") unknown(verb, kArmId);
	requireNoArgs(args, verb);
	if (verb == "DOCK?") return {device_.docked() ? "1" : "0"};
	if (verb == "GRIP?")
		return {device_.gripperClosed() ? "1" : "0", formatNumber(device_.gripperWidthMm())};
	const auto j = device_.joints();
	return numberFields(std::vector<double>(j.begin(), j.end()));
}

}  // namespace mrolr::hw_serial
