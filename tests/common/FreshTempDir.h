#pragma once
// A test's own folder under the system's temporary folder, emptied first.
#include <filesystem>
#include <string>

namespace mrolr::test_support
{
/** `<tmp>/mrolr_<name>`, removed if it was there, then created empty (or left absent). */
inline std::string freshTempDir(const std::string& name, bool create = true)
{
	const auto d = std::filesystem::temp_directory_path() / ("mrolr_" + name);
	std::filesystem::remove_all(d);
	if (create) std::filesystem::create_directories(d);
	return d.string();
}

}  // namespace mrolr::test_support
