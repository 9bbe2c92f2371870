#include <mrolr/arm/RtxOptions.h>
#include <mrolr/util/Config.h>

#include <mrolr/util/OptionsBinder.h>

#include <iomanip>
#include <ostream>

namespace mrolr::arm
{
namespace
{
constexpr const char* kMotorNames[kMotorCount] = {"column", "shoulder", "elbow",
                                                  "yaw",    "wrist1",   "wrist2"};

double readPositive(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const std::string& key)
{
	const double v = util::readDouble(cfg, section, key);
	util::requireInRange(cfg, section, key, v, 1e-12, 1e6);
	return v;
}

CountRange readRange(const mrpt::config::CConfigFileBase& cfg, const std::string& section, Motor m)
{
	const std::string base = std::string(motorName(m)) + "_counts_";
	CountRange r{util::readDouble(cfg, section, base + "min"),
	             util::readDouble(cfg, section, base + "max")};
	util::requireInRange(cfg, section, base + "max", r.max, r.min, 1e9);
	return r;
}
}  // namespace

const char* motorName(Motor m)
{
	return kMotorNames[static_cast<int>(m)];
}

void RtxOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                    const std::string& section)
{
	a2_mm = readPositive(cfg, section, "a2_mm");
	a3_mm = readPositive(cfg, section, "a3_mm");
	d6_mm = readPositive(cfg, section, "d6_mm");
	q1_fixed_deg = util::readDouble(cfg, section, "q1_fixed_deg");
	d1_top_mm = util::readDouble(cfg, section, "d1_top_mm");
	column_mm_per_count = readPositive(cfg, section, "column_mm_per_count");
	shoulder_deg_per_count = readPositive(cfg, section, "shoulder_deg_per_count");
	elbow_deg_per_count = readPositive(cfg, section, "elbow_deg_per_count");
	yaw_deg_per_count = readPositive(cfg, section, "yaw_deg_per_count");
	wrist_deg_per_count = readPositive(cfg, section, "wrist_deg_per_count");
	for (int i = 0; i < kMotorCount; ++i)
		limits[i] = readRange(cfg, section, static_cast<Motor>(i));
	wrist_radius_max_mm = readPositive(cfg, section, "wrist_radius_max_mm");
}

RtxOptions RtxOptions::fromFile(const std::string& path, const std::string& section)
{
	return util::loadOptionsFile<RtxOptions>(path, section);
}

void RtxOptions::dump(std::ostream& out) const
{
	out << std::setprecision(10) << "a2_mm = " << a2_mm << "\na3_mm = " << a3_mm
	    << "\nd6_mm = " << d6_mm << "\nq1_fixed_deg = " << q1_fixed_deg
	    << "\nd1_top_mm = " << d1_top_mm << "\ncolumn_mm_per_count = " << column_mm_per_count
	    << "\nshoulder_deg_per_count = " << shoulder_deg_per_count
	    << "\nelbow_deg_per_count = " << elbow_deg_per_count
	    << "\nyaw_deg_per_count = " << yaw_deg_per_count
	    << "\nwrist_deg_per_count = " << wrist_deg_per_count << "\n";
	for (int i = 0; i < kMotorCount; ++i)
	{
		const std::string base = std::string(kMotorNames[i]) + "_counts_";
		out << base << "min = " << limits[i].min << "\n"
		    << base << "max = " << limits[i].max << "\n";
	}
	out << "wrist_radius_max_mm = " << wrist_radius_max_mm << "\n";
}

}  // namespace mrolr::arm
