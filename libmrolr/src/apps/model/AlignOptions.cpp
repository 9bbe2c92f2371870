#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/config/CConfigFile.h>

namespace mrolr::apps
{
namespace
{
using A = AlignOptions;
constexpr auto kOpt = util::Presence::Optional;  // [align]: every key of config/model.ini

const util::OptionsBinder<A>& alignOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<A>()
	        .text("recognition_config", &A::recognition_config, kOpt)
	        .text("recognition_section", &A::recognition_section, kOpt)
	        .text("image_section", &A::image_section, kOpt)
	        .flag("upright_prior", &A::upright_prior, kOpt)
	        .integer("passes", &A::passes, 1, 100, kOpt)
	        .integer("seed_view", &A::seed_view, 0, 999, kOpt)
	        .text("match", &A::match, kOpt);  // images | shorter, checked after loading
	return b;
}
}  // namespace

void AlignOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                      const std::string& section)
{
	alignOptionsBinder().load(cfg, section, *this);
	if (match != "images" && match != "shorter")
		throw util::ConfigError(util::describeKey(cfg, section, "match") + ": '" + match +
		                        "' is not images or shorter");
}

void AlignOptions::dump(std::ostream& out) const
{
	alignOptionsBinder().dump(out, *this);
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
