#include <mrolr/apps/SlamApp.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::apps
{
namespace
{
using O = SlamRunOptions;

const util::OptionsBinder<O>& slamRunOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .text("labmate_config_file", &O::labmate_config_file)
	    .text("bisight_config_file", &O::bisight_config_file)
	    .integer("seed", &O::seed, 0, 4294967295L)
	    .number("true_velocity_noise_fraction", &O::true_velocity_noise_fraction, 0, 1)
	    .number("slip_burst_probability", &O::slip_burst_probability, 0, 1)
	    .integer("slip_burst_length_steps", &O::slip_burst_length_steps, 1, 1000)
	    .number("slip_fraction", &O::slip_fraction, 0, 1)
	    .number("image_noise_grey", &O::image_noise_grey, 0, 100)
	    .integer("texture_size_px", &O::texture_size_px, 15, 301);
	return b;
}
}  // namespace

void SlamRunOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& s)
{
	slamRunOptionsBinder().load(cfg, s, *this);
}

void SlamRunOptions::dump(std::ostream& out) const
{
	slamRunOptionsBinder().dump(out, *this);
}

}  // namespace mrolr::apps
