#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

namespace mrolr::apps
{
namespace
{
std::string readStringOr(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                         const std::string& key, const std::string& fallback)
{
	return util::hasKey(cfg, section, key) ? util::readString(cfg, section, key) : fallback;
}
}  // namespace

void AlignOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                      const std::string& section)
{
	recognition_config = readStringOr(cfg, section, "recognition_config", recognition_config);
	recognition_section = readStringOr(cfg, section, "recognition_section", recognition_section);
	image_section = readStringOr(cfg, section, "image_section", image_section);
	upright_prior = util::readBool(cfg, section, "upright_prior", upright_prior);
	passes = static_cast<int>(util::readInt(cfg, section, "passes", passes));
	seed_view = static_cast<int>(util::readInt(cfg, section, "seed_view", seed_view));
	match = readStringOr(cfg, section, "match", match);
	if (match != "images" && match != "shorter")
		throw util::ConfigError(util::describeKey(cfg, section, "match") + ": '" + match +
		                        "' is not images or shorter");
	util::requireInRange(cfg, section, "passes", passes, 1, 100);
	util::requireInRange(cfg, section, "seed_view", seed_view, 0, 999);
}

void AlignOptions::dump(std::ostream& out) const
{
	out << "recognition_config = " << recognition_config
	    << "\nrecognition_section = " << recognition_section
	    << "\nimage_section = " << image_section
	    << "\nupright_prior = " << (upright_prior ? "true" : "false") << "\npasses = " << passes
	    << "\nseed_view = " << seed_view << "\nmatch = " << match << "\n";
}

recog::RecognitionOptions alignmentRecognitionOptions(const AlignOptions& o)
{
	recog::RecognitionOptions ro;
	ro.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile(o.recognition_config)),
	                      o.recognition_section);
	// Scores by the length expected visible from a camera at the scene's origin: in 3D-only
	// matching the scene may be the accumulated model, seen from every side, with no such camera.
	if (o.match == "shorter") ro.verify_visible_only = false;
	return ro;
}

recog::ImageVerificationOptions imageOptions(const AlignOptions& o)
{
	recog::ImageVerificationOptions io;
	io.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile(o.recognition_config)),
	                      o.image_section);
	return io;
}

}  // namespace mrolr::apps
