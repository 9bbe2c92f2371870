#pragma once
/** std::optional in nlohmann::json, as its documentation shows for third-party types: an empty
 * optional is null, a null reads back as empty. Include it where an optional field is written to
 * or read from a report. */
#include <nlohmann/json.hpp>

#include <optional>

namespace nlohmann
{
template <typename T>
struct adl_serializer<std::optional<T>>
{
	static void to_json(json& j, const std::optional<T>& o)
	{
		if (o)
			j = *o;
		else
			j = nullptr;
	}
	static void from_json(const json& j, std::optional<T>& o)
	{
		if (j.is_null())
			o.reset();
		else
			o = j.get<T>();
	}
};
}  // namespace nlohmann
