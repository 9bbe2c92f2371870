// A replay's report checked against the original run's.
#include <mrolr/apps/ReplayCheck.h>

#include <set>

namespace mrolr::apps
{
namespace
{
/** Keys whose values are wall-clock times or belong to the run, not to what the robot decided. */
bool ignored(const std::string& key)
{
	static const std::set<std::string> keys = {"render_seconds", "serial_links", "replay", "plan",
	                                           "replay_divergence", "eval", "ms", "timeline"};
	return keys.count(key) || key.find("compute") != std::string::npos;
}

void compare(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
             std::vector<std::string>& out)
{
	if (b.is_null()) return;  // eval's field, not the robot's
	if (a.is_object() && b.is_object())
	{
		for (const auto& [k, v] : b.items())
			if (!ignored(k)) compare(a.contains(k) ? a[k] : nlohmann::json(), v, path.empty() ? k : path + "." + k, out);
		return;
	}
	if (a.is_array() && b.is_array() && a.size() == b.size())
	{
		for (size_t i = 0; i < a.size(); ++i)
			compare(a[i], b[i], path + "[" + std::to_string(i) + "]", out);
		return;
	}
	if (a != b) out.push_back(path);
}
}  // namespace

std::vector<std::string> reportDifferences(const nlohmann::json& original,
                                           const nlohmann::json& replay, size_t max_listed)
{
	std::vector<std::string> all;
	compare(original, replay, "", all);
	if (all.size() <= max_listed) return all;
	std::vector<std::string> out(all.begin(), all.begin() + max_listed);
	out.push_back("… " + std::to_string(all.size()) + " differences in all");
	return out;
}

}  // namespace mrolr::apps
