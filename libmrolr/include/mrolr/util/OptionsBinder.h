#pragma once
/** One declaration per key: an options struct's keys are declared once, each with its member,
 * its range (the unit is in the key's name, DESIGN.md) and whether it may be absent, and that one
 * declaration loads, checks and dumps them (in the spirit of MRPT's MRPT_LOAD_CONFIG_VAR and
 * mp2p_icp's MCP_LOAD_REQ / MCP_LOAD_OPT).
 *
 * The policy (docs/config.md): a key is required. A key is optional only where absence has a
 * meaning of its own (a stage a user may leave out, a device that may be missing), and then the
 * struct's default stands; it is declared Presence::Optional with that reason next to it. A section
 * may be optional as a whole (the caller checks cfg.sectionExists). Choices are parsed into enums
 * at load time; an unknown name is an error naming the choices. Every error names file, section
 * and key (util::ConfigError).
 *
 * ```
 * const util::OptionsBinder<Options>& binder()
 * {
 *     static const auto b = util::OptionsBinder<Options>()
 *         .number("radius_tol_mm", &Options::radius_tol_mm, 0, 1000)
 *         .integer("max_hypotheses", &Options::max_hypotheses, 1, 100000)
 *         .flag("limbs", &Options::limbs, util::Presence::Optional)
 *         .choice("run_when", &Options::run_when, {{"always", When::Always}, {"never", When::Never}});
 *     return b;
 * }
 * ```
 */
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mrolr::util
{
/** Whether a key must be in its section. */
enum class Presence
{
	Required,
	Optional  ///< absent: the struct's default stands
};

/** A choice's names and values, in the order they are listed in errors and docs. */
template <class E>
using ChoiceNames = std::vector<std::pair<std::string, E>>;

/** "a, b, c": the names of a choice, for errors. */
template <class E>
std::string listNames(const ChoiceNames<E>& names)
{
	std::string out;
	for (const auto& [n, v] : names) out += (out.empty() ? "" : ", ") + n;
	return out;
}

/** The name of @p value among @p names ("?" when it has none): what a dump writes. */
template <class E>
std::string nameOf(const ChoiceNames<E>& names, const E& value)
{
	for (const auto& [n, v] : names)
		if (v == value) return n;
	return "?";
}

template <class Options>
class OptionsBinder
{
	/** The field @p m names in @p o: a pointer to a member, or an accessor `T& (Options&)` for a
	 * field of a nested struct. */
	template <class M>
	static auto& field(Options& o, M m)
	{
		if constexpr (std::is_member_object_pointer_v<M>)
			return o.*m;
		else
			return m(o);
	}
	template <class M>
	static const auto& field(const Options& o, M m)
	{
		return field(const_cast<Options&>(o), m);  // the accessor only names the field
	}

   public:
	/** A real number in [lo, hi]. */
	template <class M>
	OptionsBinder& number(const std::string& key, M member, double lo, double hi,
	                      Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           { field(o, member) = readDoubleInRange(cfg, s, key, lo, hi); },
		           [=](std::ostream& out, const Options& o) { out << field(o, member); });
	}

	/** A whole number in [lo, hi] (int or long members). */
	template <class M>
	OptionsBinder& integer(const std::string& key, M member, long lo, long hi,
	                       Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           {
			           const long v = readInt(cfg, s, key);
			           requireInRange(cfg, s, key, static_cast<double>(v), static_cast<double>(lo),
			                          static_cast<double>(hi));
			           auto& f = field(o, member);
			           f = static_cast<std::remove_reference_t<decltype(f)>>(v);
		           },
		           [=](std::ostream& out, const Options& o) { out << field(o, member); });
	}

	/** true/false, yes/no, on/off, 1/0. */
	template <class M>
	OptionsBinder& flag(const std::string& key, M member, Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           { field(o, member) = readBool(cfg, s, key, field(o, member)); },
		           [=](std::ostream& out, const Options& o)
		           { out << (field(o, member) ? "true" : "false"); });
	}

	/** Free text (a file name, a label). */
	template <class M>
	OptionsBinder& text(const std::string& key, M member, Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           { field(o, member) = readString(cfg, s, key); },
		           [=](std::ostream& out, const Options& o) { out << field(o, member); });
	}

	/** One of @p names, parsed into its enum value. */
	template <class E, class M>
	OptionsBinder& choice(const std::string& key, M member, ChoiceNames<E> names,
	                      Presence presence = Presence::Required)
	{
		return add(
		    key, presence,
		    [=](const Cfg& cfg, const std::string& s, Options& o)
		    {
			    const std::string v = readString(cfg, s, key);
			    for (const auto& [n, e] : names)
				    if (n == v)
				    {
					    field(o, member) = e;
					    return;
				    }
			    throw ConfigError(describeKey(cfg, s, key) + ": '" + v + "' is not one of " +
			                      listNames(names));
		    },
		    [=](std::ostream& out, const Options& o) { out << nameOf(names, field(o, member)); });
	}

	/** Keys that were once read here and are now constants of the step (members with their
	 * value and reason in @p where): a file that still sets one is refused, naming it, so that an
	 * old file never runs with a value silently ignored. */
	OptionsBinder& fixed(std::vector<std::string> keys, std::string where)
	{
		fixed_ = std::move(keys);
		fixed_where_ = std::move(where);
		return *this;
	}

	/** Exactly @p count numbers, each in [lo, hi], into a std::vector<double> or a fixed-size
	 * array of @p count (std::array<double, N>). */
	template <class M>
	OptionsBinder& numbers(const std::string& key, M member, size_t count, double lo, double hi,
	                       Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           {
			           auto v = readDoubles(cfg, s, key, count);
			           for (const double x : v) requireInRange(cfg, s, key, x, lo, hi);
			           auto& f = field(o, member);
			           if constexpr (std::is_same_v<std::decay_t<decltype(f)>, std::vector<double>>)
				           f = std::move(v);
			           else
				           std::copy(v.begin(), v.end(), f.begin());
		           },
		           [=](std::ostream& out, const Options& o)
		           {
			           const auto& v = field(o, member);
			           for (size_t i = 0; i < v.size(); ++i) out << (i ? " " : "") << v[i];
		           });
	}

	/** Three numbers into a 3-vector (Eigen::Vector3d: constructed from three, indexed by []),
	 * each in [lo, hi]. */
	template <class M>
	OptionsBinder& vector3(const std::string& key, M member, double lo, double hi,
	                       Presence presence = Presence::Required)
	{
		return add(key, presence,
		           [=](const Cfg& cfg, const std::string& s, Options& o)
		           {
			           const auto v = readDoubles(cfg, s, key, 3);
			           for (const double x : v) requireInRange(cfg, s, key, x, lo, hi);
			           auto& f = field(o, member);
			           f = std::remove_reference_t<decltype(f)>(v[0], v[1], v[2]);
		           },
		           [=](std::ostream& out, const Options& o)
		           {
			           const auto& v = field(o, member);
			           out << v[0] << " " << v[1] << " " << v[2];
		           });
	}

	/** Reads every declared key of @p section into @p o; a required key that is missing, a
	 * malformed value or one out of range throws ConfigError naming file, section and key. */
	void load(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
	          Options& o) const
	{
		for (const auto& key : fixed_)
			if (hasKey(cfg, section, key))
				throw ConfigError(describeKey(cfg, section, key) + ": no longer a configuration key; " +
				                  fixed_where_ + " fixes it in code (docs/config.md \"Fixed in code\"): "
				                  "remove the line");
		for (const auto& k : keys_)
		{
			if (k.presence == Presence::Optional && !hasKey(cfg, section, k.key)) continue;
			if (!hasKey(cfg, section, k.key))
				throw ConfigError(describeKey(cfg, section, k.key) + ": missing");
			k.load(cfg, section, o);
		}
	}

	/** Every declared key as `key = value` lines, in declaration order. */
	void dump(std::ostream& out, const Options& o) const
	{
		for (const auto& k : keys_)
		{
			out << k.key << " = ";
			k.dump(out, o);
			out << "\n";
		}
	}

	/** The declared keys, in order. */
	std::vector<std::string> keys() const
	{
		std::vector<std::string> out;
		for (const auto& k : keys_) out.push_back(k.key);
		return out;
	}

   private:
	using Cfg = mrpt::config::CConfigFileBase;
	std::vector<std::string> fixed_;
	std::string fixed_where_;
	struct Key
	{
		std::string key;
		Presence presence;
		std::function<void(const Cfg&, const std::string&, Options&)> load;
		std::function<void(std::ostream&, const Options&)> dump;
	};
	std::vector<Key> keys_;

	OptionsBinder& add(const std::string& key, Presence presence,
	                   std::function<void(const Cfg&, const std::string&, Options&)> load,
	                   std::function<void(std::ostream&, const Options&)> dump)
	{
		for (const auto& k : keys_)
			if (k.key == key) throw std::logic_error("OptionsBinder: key '" + key + "' declared twice");
		keys_.push_back({key, presence, std::move(load), std::move(dump)});
		return *this;
	}
};

/** @p section of the `.ini` file @p path loaded into a default Options (its
 * loadFromConfigFile); ConfigError naming the path when the file cannot be read. */
template <class Options>
Options loadOptionsFile(const std::string& path, const std::string& section)
{
	const auto cfg = openConfigFile(path);
	Options o;
	o.loadFromConfigFile(cfg, section);
	return o;
}

}  // namespace mrolr::util
