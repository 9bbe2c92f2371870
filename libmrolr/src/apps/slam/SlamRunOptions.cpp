#include <mrolr/apps/SlamApp.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::apps
{
void SlamRunOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& s)
{
	using util::readDouble;
	labmate_config_file = util::readString(cfg, s, "labmate_config_file");
	bisight_config_file = util::readString(cfg, s, "bisight_config_file");
	seed = static_cast<unsigned>(util::readInt(cfg, s, "seed"));
	true_velocity_noise_fraction = readDouble(cfg, s, "true_velocity_noise_fraction");
	util::requireInRange(cfg, s, "true_velocity_noise_fraction", true_velocity_noise_fraction, 0,
	                     1);
	slip_burst_probability = readDouble(cfg, s, "slip_burst_probability");
	util::requireInRange(cfg, s, "slip_burst_probability", slip_burst_probability, 0, 1);
	slip_burst_length_steps = static_cast<int>(util::readInt(cfg, s, "slip_burst_length_steps"));
	util::requireInRange(cfg, s, "slip_burst_length_steps", slip_burst_length_steps, 1, 1000);
	slip_fraction = readDouble(cfg, s, "slip_fraction");
	util::requireInRange(cfg, s, "slip_fraction", slip_fraction, 0, 1);
	image_noise_grey = readDouble(cfg, s, "image_noise_grey");
	util::requireInRange(cfg, s, "image_noise_grey", image_noise_grey, 0, 100);
	texture_size_px = static_cast<int>(util::readInt(cfg, s, "texture_size_px"));
	util::requireInRange(cfg, s, "texture_size_px", texture_size_px, 15, 301);
}

void SlamRunOptions::dump(std::ostream& out) const
{
	out << "labmate_config_file = " << labmate_config_file
	    << "\nbisight_config_file = " << bisight_config_file << "\nseed = " << seed
	    << "\ntrue_velocity_noise_fraction = " << true_velocity_noise_fraction
	    << "\nslip_burst_probability = " << slip_burst_probability
	    << "\nslip_burst_length_steps = " << slip_burst_length_steps
	    << "\nslip_fraction = " << slip_fraction << "\nimage_noise_grey = " << image_noise_grey
	    << "\ntexture_size_px = " << texture_size_px << "\n";
}

}  // namespace mrolr::apps
