#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <fstream>
#include <iomanip>
#include <ostream>

namespace mrolr::geometry
{
namespace
{
double readPositive(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const std::string& key, double hi)
{
	const double v = util::readDouble(cfg, section, key);
	util::requireInRange(cfg, section, key, v, 1e-12, hi);
	return v;
}

int readPixels(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
               const std::string& key)
{
	const long v = util::readInt(cfg, section, key);
	util::requireInRange(cfg, section, key, static_cast<double>(v), 1, 100000);
	return static_cast<int>(v);
}
}  // namespace

void BiSightOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	using util::readDouble;
	interocular_m = readPositive(cfg, section, "interocular_m", 10);
	head_height_m = readDouble(cfg, section, "head_height_m");
	pan_offset_m = readDouble(cfg, section, "pan_offset_m");
	tilt_offset_m = readDouble(cfg, section, "tilt_offset_m");
	optic_offset_m = readDouble(cfg, section, "optic_offset_m");
	focal_px_u = readPositive(cfg, section, "focal_px_u", 1e7);
	focal_px_v = readPositive(cfg, section, "focal_px_v", 1e7);
	u0_px = readDouble(cfg, section, "u0_px");
	v0_px = readDouble(cfg, section, "v0_px");
	image_width_px = readPixels(cfg, section, "image_width_px");
	image_height_px = readPixels(cfg, section, "image_height_px");
	pan_limit_deg = readPositive(cfg, section, "pan_limit_deg", 180);
	tilt_limit_deg = readPositive(cfg, section, "tilt_limit_deg", 90);
	vergence_limit_deg = readPositive(cfg, section, "vergence_limit_deg", 90);
}

BiSightOptions BiSightOptions::fromFile(const std::string& path, const std::string& section)
{
	if (!std::ifstream(path).good())
		throw util::ConfigError(path + ": cannot open the configuration file");
	mrpt::config::CConfigFile cfg(path);
	BiSightOptions o;
	o.loadFromConfigFile(cfg, section);
	return o;
}

void BiSightOptions::dump(std::ostream& out) const
{
	out << std::setprecision(17) << "interocular_m = " << interocular_m
	    << "\nhead_height_m = " << head_height_m << "\npan_offset_m = " << pan_offset_m
	    << "\ntilt_offset_m = " << tilt_offset_m << "\noptic_offset_m = " << optic_offset_m
	    << "\nfocal_px_u = " << focal_px_u << "\nfocal_px_v = " << focal_px_v
	    << "\nu0_px = " << u0_px << "\nv0_px = " << v0_px << "\nimage_width_px = " << image_width_px
	    << "\nimage_height_px = " << image_height_px << "\npan_limit_deg = " << pan_limit_deg
	    << "\ntilt_limit_deg = " << tilt_limit_deg
	    << "\nvergence_limit_deg = " << vergence_limit_deg << "\n";
}

PinholeCamera BiSightOptions::camera() const
{
	PinholeCamera c;
	c.focal_px_u = focal_px_u;
	c.focal_px_v = focal_px_v;
	c.u0_px = u0_px;
	c.v0_px = v0_px;
	c.width_px = image_width_px;
	c.height_px = image_height_px;
	return c;
}

}  // namespace mrolr::geometry
