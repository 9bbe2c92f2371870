#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <iomanip>
#include <ostream>

namespace mrolr::geometry
{
namespace
{
using B = BiSightOptions;
constexpr double kPositive = 1e-12;  // lengths and focal lengths: strictly positive
constexpr double kFar_m = 1e3;       // offsets and heights: any the head could have

const util::OptionsBinder<B>& binder()
{
	static const auto b = util::OptionsBinder<B>()
	                          .number("interocular_m", &B::interocular_m, kPositive, 10)
	                          .number("head_height_m", &B::head_height_m, -kFar_m, kFar_m)
	                          .number("pan_offset_m", &B::pan_offset_m, -kFar_m, kFar_m)
	                          .number("tilt_offset_m", &B::tilt_offset_m, -kFar_m, kFar_m)
	                          .number("optic_offset_m", &B::optic_offset_m, -kFar_m, kFar_m)
	                          .number("focal_px_u", &B::focal_px_u, kPositive, 1e7)
	                          .number("focal_px_v", &B::focal_px_v, kPositive, 1e7)
	                          .number("u0_px", &B::u0_px, -1e7, 1e7)
	                          .number("v0_px", &B::v0_px, -1e7, 1e7)
	                          .integer("image_width_px", &B::image_width_px, 1, 100000)
	                          .integer("image_height_px", &B::image_height_px, 1, 100000)
	                          .number("pan_limit_deg", &B::pan_limit_deg, kPositive, 180)
	                          .number("tilt_limit_deg", &B::tilt_limit_deg, kPositive, 90)
	                          .number("vergence_limit_deg", &B::vergence_limit_deg, kPositive, 90);
	return b;
}
}  // namespace

void BiSightOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	binder().load(cfg, section, *this);
}

BiSightOptions BiSightOptions::fromFile(const std::string& path, const std::string& section)
{
	return util::loadOptionsFile<BiSightOptions>(path, section);
}

void BiSightOptions::dump(std::ostream& out) const
{
	out << std::setprecision(17);
	binder().dump(out, *this);
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
