#include <mrolr/arm/RtxOptions.h>

#include <mrolr/util/OptionsBinder.h>

#include <iomanip>
#include <ostream>

namespace mrolr::arm
{
namespace
{
constexpr const char* kMotorNames[kMotorCount] = {"column", "shoulder", "elbow",
                                                  "yaw",    "wrist1",   "wrist2"};

using R = RtxOptions;
constexpr double kPositive = 1e-12;  // lengths and scale factors: strictly positive

const util::OptionsBinder<R>& binder()
{
	static const auto b = []
	{
		auto d = util::OptionsBinder<R>()
		             .number("a2_mm", &R::a2_mm, kPositive, 1e6)
		             .number("a3_mm", &R::a3_mm, kPositive, 1e6)
		             .number("d6_mm", &R::d6_mm, kPositive, 1e6)
		             .number("q1_fixed_deg", &R::q1_fixed_deg, -360, 360)
		             .number("d1_top_mm", &R::d1_top_mm, -1e6, 1e6)
		             .number("column_mm_per_count", &R::column_mm_per_count, kPositive, 1e6)
		             .number("shoulder_deg_per_count", &R::shoulder_deg_per_count, kPositive, 1e6)
		             .number("elbow_deg_per_count", &R::elbow_deg_per_count, kPositive, 1e6)
		             .number("yaw_deg_per_count", &R::yaw_deg_per_count, kPositive, 1e6)
		             .number("wrist_deg_per_count", &R::wrist_deg_per_count, kPositive, 1e6);
		for (int i = 0; i < kMotorCount; ++i)  // <motor>_counts_min, <motor>_counts_max
		{
			const std::string base = std::string(kMotorNames[i]) + "_counts_";
			d.number(base + "min", [i](R& o) -> double& { return o.limits[i].min; }, -1e9, 1e9);
			d.number(base + "max", [i](R& o) -> double& { return o.limits[i].max; }, -1e9, 1e9);
		}
		d.number("wrist_radius_max_mm", &R::wrist_radius_max_mm, kPositive, 1e6);
		return d;
	}();
	return b;
}
}  // namespace

const char* motorName(Motor m)
{
	return kMotorNames[static_cast<int>(m)];
}

void RtxOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                    const std::string& section)
{
	binder().load(cfg, section, *this);
	for (int i = 0; i < kMotorCount; ++i)
		util::requireInRange(cfg, section, std::string(kMotorNames[i]) + "_counts_max",
		                     limits[i].max, limits[i].min, 1e9);
}

RtxOptions RtxOptions::fromFile(const std::string& path, const std::string& section)
{
	return util::loadOptionsFile<RtxOptions>(path, section);
}

void RtxOptions::dump(std::ostream& out) const
{
	out << std::setprecision(10);
	binder().dump(out, *this);
}

}  // namespace mrolr::arm
