#pragma once
// MRPT's own rosbag2rawlog on a bag, with the shipped configuration, and rawlog-edit on what it
// gives back (a client no one here wrote): how many objects the rawlog holds.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace mrolr::test_support
{
/** The objects rawlog-edit counts in rosbag2rawlog's conversion of @p bag (written to @p back);
 * throws naming the command when either tool fails. */
inline size_t objectsBackFromBag(const std::string& bag, const std::string& back)
{
	const std::string info = back + ".info.txt";
	const std::string cmd = "rosbag2rawlog -w -c " + std::string(MROLR_SOURCE_DIR) +
	                        "/config/rosbag2rawlog.yml -f world -o " + back + " " + bag +
	                        " > /dev/null 2>&1 && rawlog-edit --info -i " + back + " > " + info +
	                        " 2>&1";
	if (std::system(cmd.c_str()) != 0) throw std::runtime_error("failed: " + cmd);
	std::stringstream s;
	s << std::ifstream(info).rdbuf();
	const std::string key = "Overall number of objects";
	const auto at = s.str().find(key);
	if (at == std::string::npos) throw std::runtime_error("rawlog-edit --info: no object count");
	const auto colon = s.str().find(':', at);
	return std::stoul(s.str().substr(colon + 1));
}

}  // namespace mrolr::test_support
