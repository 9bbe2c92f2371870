#pragma once
/** Shared command-line plumbing for every MROLR app: the same exit codes (0 ok, 1 runtime error,
 * 2 bad arguments), negative numbers accepted as positional arguments, and one place that catches
 * exceptions at the top of main(). */

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrolr::util
{
/** Thrown for bad command-line arguments; the app prints it with the usage and exits 2. */
class UsageError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

/** argv as strings, with every token that is a negative number ("-0.2", "-3e-4") prefixed by one
 * space so that TCLAP does not take it for a switch; mrolr::util::parseDouble trims it again. */
std::vector<std::string> argsWithNegativeNumbersProtected(int argc, const char* const* argv);

/** Parses a positional number, throwing UsageError("<what>: '<text>' is not a number"). */
double parseNumberArg(const std::string& text, const std::string& what);

/** Parses "a,b,c" into exactly @p count numbers or throws UsageError naming @p what. */
std::vector<double> parseNumberList(const std::string& text, size_t count, const std::string& what);

/** Runs @p body; prints "<prog>: error: <what>" to stderr for exceptions and returns the exit code
 * (kExitUsage for UsageError, kExitFailure for anything else). */
int runMain(const std::string& prog, const std::function<int()>& body);

}  // namespace mrolr::util

namespace mrolr::util
{
/** A shipped file (config/..., maps/..., datasets/...) as given when it exists from the working
 * directory (or is absolute), else the same relative path inside the source tree the binary was
 * built from, else @p path unchanged (so that the caller's "cannot open" names what was asked). */
std::string projectFile(const std::string& path);

/** As projectFile, but throws std::runtime_error("file '<path>' does not exist") when neither
 * exists. */
std::string requireProjectFile(const std::string& path);

}  // namespace mrolr::util
