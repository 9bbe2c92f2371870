#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <functional>
#include <stdexcept>

namespace mrolr::recog
{
namespace
{
/** One per-level key: its name, its accessor and its allowed range. */
struct LevelKey
{
	const char* name;
	std::function<double&(LevelParams&)> field;
	double lo, hi;
};

const std::vector<LevelKey>& levelKeys()
{
	static const std::vector<LevelKey> keys = {
	    {"position_error_mm", [](LevelParams& p) -> double& { return p.position_error_mm; }, 0.01,
	     1000},
	    {"rotation_deg", [](LevelParams& p) -> double& { return p.rotation_deg; }, 0.01, 45},
	    {"length_threshold_mm", [](LevelParams& p) -> double& { return p.length_threshold_mm; }, 0,
	     1e4},
	    {"max_rotation_deg", [](LevelParams& p) -> double& { return p.max_rotation_deg; }, 0.01,
	     180},
	    {"max_translation_mm", [](LevelParams& p) -> double& { return p.max_translation_mm; }, 0.01,
	     1e4},
	    {"length_ratio", [](LevelParams& p) -> double& { return p.length_ratio; }, 0, 1},
	    {"verify_min_score", [](LevelParams& p) -> double& { return p.verify_min_score; }, 0, 1},
	};
	return keys;
}

void readLevelKey(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                  const LevelKey& key, std::vector<LevelParams>& levels)
{
	const auto values = util::readDoubles(cfg, section, key.name, levels.size());
	for (size_t i = 0; i < levels.size(); ++i)
	{
		util::requireInRange(cfg, section, key.name, values[i], key.lo, key.hi);
		key.field(levels[i]) = values[i];
	}
}

/** An optional use | add | ignore key (ModelTable's file_cliques). */
void readCliqueUse(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const char* key, std::string& value)
{
	if (util::hasKey(cfg, section, key)) value = util::readString(cfg, section, key);
	if (value != "use" && value != "add" && value != "ignore")
		throw util::ConfigError(util::describeKey(cfg, section, key) + ": '" + value +
		                        "' is not one of use, add, ignore");
}

void readCliqueSizes(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                     std::vector<LevelParams>& levels)
{
	const auto values = util::readDoubles(cfg, section, "clique_size", levels.size());
	for (size_t i = 0; i < levels.size(); ++i)
	{
		util::requireInRange(cfg, section, "clique_size", values[i], 2, 50);
		if (values[i] != static_cast<int>(values[i]))
			throw util::ConfigError(util::describeKey(cfg, section, "clique_size") +
			                        ": values must be integers");
		levels[i].clique_size = static_cast<int>(values[i]);
	}
}

void dumpLevelKey(std::ostream& out, const LevelKey& key, const std::vector<LevelParams>& levels)
{
	out << key.name << " =";
	for (auto p : levels) out << " " << key.field(p);
	out << "\n";
}
using R = RecognitionOptions;
constexpr auto kOpt = util::Presence::Optional;

/** The keys besides the level schedule (one value per level, readLevelKey) and the clique-use
 * choices (readCliqueUse, which ModelTable also checks). */
const util::OptionsBinder<R>& binder()
{
	static const auto b =
	    util::OptionsBinder<R>()
	        .choice("pose_method", &R::pose_method,
	                util::ChoiceNames<PoseMethod>{{"faugeras_hebert", PoseMethod::FaugerasHebert},
	                                              {"arun", PoseMethod::Arun},
	                                              {"both", PoseMethod::Both}})
	        .choice("auto_cliques", &R::auto_cliques,
	                util::ChoiceNames<std::string>{{"recog", "recog"}, {"model", "model"}}, util::Presence::Optional)
	        .integer("auto_clique_count", &R::auto_clique_count, 1, 1000, util::Presence::Optional)
	        .integer("auto_clique_size", &R::auto_clique_size, 2, 50, util::Presence::Optional)
	        .integer("max_search_nodes", &R::max_search_nodes, 10, 10000000, util::Presence::Optional)
	        .integer("refine_iterations", &R::refine_iterations, 0, 20, util::Presence::Optional)
	        .integer("verify_clusters", &R::verify_clusters, 1, 10000, util::Presence::Optional)
	        .integer("confirm_levels", &R::confirm_levels, 0, 100, util::Presence::Optional)
	        .number("verify_position_error_mm", &R::verify_position_error_mm, 0.01, 1000, util::Presence::Optional)
	        .number("verify_rotation_deg", &R::verify_rotation_deg, 0.01, 90, util::Presence::Optional)
	        // later refinements: absent, the measured defaults stand (docs/recog.md)
	        .flag("skip_hopeless_levels", &R::skip_hopeless_levels, kOpt)
	        .flag("verify_visible_only", &R::verify_visible_only, kOpt)
	        .number("visible_min_score_factor", &R::visible_min_score_factor, 0.1, 10, kOpt)
	        .number("upright_max_tilt_deg", &R::upright_max_tilt_deg, 0, 180, kOpt)
	        .number("ambiguity_margin", &R::ambiguity_margin, 0, 1, kOpt)
	        .number("ambiguity_min_turn_deg", &R::ambiguity_min_turn_deg, 0, 180, kOpt)
	        .number("ambiguity_symmetry_mm", &R::ambiguity_symmetry_mm, 0, 1000, kOpt)
	        .number("ambiguity_symmetry_share", &R::ambiguity_symmetry_share, 0, 1, kOpt);
	return b;
}
}  // namespace

RecognitionOptions RecognitionOptions::defaults()
{
	// clique, beta mm, theta deg, min len mm, max rot deg, max trans mm, len ratio, verify score
	static const double table[12][8] = {
	    {5, 2, 1.5, 15, 3, 6, 0.7, 0.33},  {5, 3, 2, 15, 3, 6, 0.6, 0.33},
	    {4, 3, 2, 12, 4, 8, 0.6, 0.34},    {4, 4, 3, 12, 4, 8, 0.5, 0.35},
	    {4, 5, 3, 10, 5, 10, 0.5, 0.35},   {4, 6, 4, 10, 5, 10, 0.4, 0.36},
	    {3, 6, 4, 10, 6, 12, 0.4, 0.36},   {3, 8, 5, 8, 6, 12, 0.35, 0.37},
	    {3, 8, 6, 8, 8, 15, 0.3, 0.38},    {3, 10, 7, 8, 8, 15, 0.3, 0.39},
	    {3, 12, 8, 6, 10, 20, 0.25, 0.40}, {3, 15, 10, 6, 10, 20, 0.2, 0.42}};
	RecognitionOptions o;
	for (const auto& r : table)
		o.levels.push_back({static_cast<int>(r[0]), r[1], r[2], r[3], r[4], r[5], r[6], r[7]});
	return o;
}

void RecognitionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                            const std::string& section)
{
	const long n = util::readInt(cfg, section, "levels");
	util::requireInRange(cfg, section, "levels", static_cast<double>(n), 1, 100);
	std::vector<LevelParams> lv(static_cast<size_t>(n));
	readCliqueSizes(cfg, section, lv);
	for (const auto& key : levelKeys()) readLevelKey(cfg, section, key, lv);
	levels = std::move(lv);
	binder().load(cfg, section, *this);
	readCliqueUse(cfg, section, "file_cliques", file_cliques);
	readCliqueUse(cfg, section, "file_cliques_with_images", file_cliques_with_images);
}

void RecognitionOptions::dump(std::ostream& out) const
{
	out << "levels = " << levels.size() << "\nclique_size =";
	for (const auto& p : levels) out << " " << p.clique_size;
	out << "\n";
	for (const auto& key : levelKeys()) dumpLevelKey(out, key, levels);
	binder().dump(out, *this);
	out << "file_cliques = " << file_cliques
	    << "\nfile_cliques_with_images = " << file_cliques_with_images << "\n";
}

}  // namespace mrolr::recog
