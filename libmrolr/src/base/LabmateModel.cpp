#include <mrolr/base/LabmateModel.h>
#include <mrolr/util/OptionsBinder.h>

#include "ArcFunctions.h"

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace mrolr::base
{
using detail::arcTerms;

namespace
{
using O = LabmateOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& labmateOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("wheel_half_separation_m", &O::wheel_half_separation_m, 1e-3, 10)
	    .number("velocity_noise_fraction", &O::velocity_noise_fraction, 0, 1)
	    .number("translation_speed_mps", &O::translation_speed_mps, 1e-6, 10)
	    .number("rotation_wheel_speed_mps", &O::rotation_wheel_speed_mps, 1e-6, 10)
	    // the encoder and the body's shape: a model of the thesis's odometry needs neither
	    .number("encoder_ticks_per_m", &O::encoder_ticks_per_m, 1, 1e8, kOpt)
	    .number("footprint_length_m", &O::footprint_length_m, 0.05, 5, kOpt)
	    .number("footprint_width_m", &O::footprint_width_m, 0.05, 5, kOpt)
	    .number("deck_height_m", &O::deck_height_m, 0.01, 3, kOpt)
	    .number("mast_half_width_m", &O::mast_half_width_m, 0, 1, kOpt)
	    .number("mast_top_height_m", &O::mast_top_height_m, 0.01, 5, kOpt);
	return b;
}
}  // namespace

void LabmateOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	labmateOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "mast_top_height_m", mast_top_height_m, deck_height_m, 5);
}

void LabmateOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[labmate]\n";
	labmateOptionsBinder().dump(out, *this);
}

LabmateModel::LabmateModel(const LabmateOptions& options) : options_(options)
{
	if (!(options.wheel_half_separation_m > 0))
		throw std::invalid_argument("LabmateModel: wheel_half_separation_m must be positive");
}

double LabmateModel::turnAngle(const WheelControl& u) const
{
	return (u.v1_mps - u.v2_mps) * u.dt_s / (2 * options_.wheel_half_separation_m);
}

Eigen::Vector3d LabmateModel::move(const Eigen::Vector3d& x_v, const WheelControl& u) const
{
	const double th = turnAngle(u), s = arcLength(u);
	const auto k = arcTerms(th);
	const double c = std::cos(x_v[2]), sn = std::sin(x_v[2]);
	return {x_v[0] + s * (c * k.a - sn * k.b), x_v[1] + s * (sn * k.a + c * k.b), x_v[2] + th};
}

Eigen::Matrix3d LabmateModel::jacobianState(const Eigen::Vector3d& x_v, const WheelControl& u) const
{
	// ∂z'/∂φ = −Δx and ∂x'/∂φ = Δz (eq 5.16).
	const Eigen::Vector3d d = move(x_v, u) - x_v;
	Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
	F(0, 2) = -d[1];
	F(1, 2) = d[0];
	return F;
}

Eigen::Matrix<double, 3, 2> LabmateModel::jacobianControl(const Eigen::Vector3d& x_v,
                                                          const WheelControl& u) const
{
	const double th = turnAngle(u), s = arcLength(u);
	const auto k = arcTerms(th);
	const double c = std::cos(x_v[2]), sn = std::sin(x_v[2]);
	// f depends on u through s and θ: ∂s/∂v_i = Δt/2, ∂θ/∂v1 = −∂θ/∂v2 = Δt/(2 D1) (eq 5.14).
	const Eigen::Vector3d df_ds(c * k.a - sn * k.b, sn * k.a + c * k.b, 0);
	const Eigen::Vector3d df_dth(s * (c * k.da - sn * k.db), s * (sn * k.da + c * k.db), 1);
	const double ds = u.dt_s / 2, dth = u.dt_s / (2 * options_.wheel_half_separation_m);
	Eigen::Matrix<double, 3, 2> G;
	G.col(0) = df_ds * ds + df_dth * dth;
	G.col(1) = df_ds * ds - df_dth * dth;
	return G;
}

Eigen::Matrix2d LabmateModel::controlCovariance(const WheelControl& u) const
{
	const double f = options_.velocity_noise_fraction;
	return Eigen::Vector2d(std::pow(f * u.v1_mps, 2), std::pow(f * u.v2_mps, 2)).asDiagonal();
}

Eigen::Matrix3d LabmateModel::processNoise(const Eigen::Vector3d& x_v, const WheelControl& u) const
{
	const auto G = jacobianControl(x_v, u);
	return G * controlCovariance(u) * G.transpose();
}

WheelControl LabmateModel::rotationControl(double angle_rad) const
{
	const double w = options_.rotation_wheel_speed_mps;
	const double dt = std::abs(angle_rad) * options_.wheel_half_separation_m / w;
	const double sgn = angle_rad >= 0 ? 1.0 : -1.0;
	return {sgn * w, -sgn * w, dt};
}

WheelControl LabmateModel::translationControl(double distance_m) const
{
	const double v = options_.translation_speed_mps;
	const double sgn = distance_m >= 0 ? 1.0 : -1.0;
	return {sgn * v, sgn * v, std::abs(distance_m) / v};
}

}  // namespace mrolr::base
