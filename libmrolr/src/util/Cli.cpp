#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <filesystem>
#include <iostream>

namespace mrolr::util
{
std::vector<std::string> argsWithNegativeNumbersProtected(int argc, const char* const* argv)
{
	std::vector<std::string> out;
	out.reserve(static_cast<size_t>(argc));
	for (int i = 0; i < argc; ++i)
	{
		std::string a = argv[i];
		double v = 0;
		if (i > 0 && a.size() > 1 && a[0] == '-' && parseDouble(a, v)) a = " " + a;
		out.push_back(std::move(a));
	}
	return out;
}

double parseNumberArg(const std::string& text, const std::string& what)
{
	double v = 0;
	if (!parseDouble(text, v)) throw UsageError(what + ": '" + text + "' is not a number");
	return v;
}

std::vector<double> parseNumberList(const std::string& text, size_t count, const std::string& what)
{
	std::vector<double> out;
	for (const auto& f : splitFields(text)) out.push_back(parseNumberArg(f, what));
	if (out.size() != count)
		throw UsageError(
			what + ": expected " + std::to_string(count) + " comma-separated numbers, got '" +
			text + "'");
	return out;
}

int runMain(const std::string& prog, const std::function<int()>& body)
{
	try
	{
		return body();
	}
	catch (const UsageError& e)
	{
		std::cerr << prog << ": " << e.what() << "\n(try " << prog << " --help)\n";
		return kExitUsage;
	}
	catch (const std::exception& e)
	{
		std::cerr << prog << ": error: " << e.what() << "\n";
		return kExitFailure;
	}
}

}  // namespace mrolr::util

namespace mrolr::util
{
std::string projectFile(const std::string& path)
{
	if (path.empty() || std::filesystem::exists(path) || path.front() == '/') return path;
	const std::string in_source = std::string(MROLR_SOURCE_DIR) + "/" + path;
	return std::filesystem::exists(in_source) ? in_source : path;
}

std::string requireProjectFile(const std::string& path)
{
	const std::string found = projectFile(path);
	if (!std::filesystem::exists(found))
		throw std::runtime_error("file '" + path + "' does not exist");
	return found;
}

}  // namespace mrolr::util
