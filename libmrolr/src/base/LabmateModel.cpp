#include <mrolr/base/LabmateModel.h>
#include <mrolr/util/Config.h>

#include "ArcFunctions.h"

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace mrolr::base
{
using detail::arcTerms;

void LabmateOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	using util::readDouble;
	using util::requireInRange;
	wheel_half_separation_m = readDouble(cfg, section, "wheel_half_separation_m");
	requireInRange(cfg, section, "wheel_half_separation_m", wheel_half_separation_m, 1e-3, 10);
	velocity_noise_fraction = readDouble(cfg, section, "velocity_noise_fraction");
	requireInRange(cfg, section, "velocity_noise_fraction", velocity_noise_fraction, 0, 1);
	translation_speed_mps = readDouble(cfg, section, "translation_speed_mps");
	requireInRange(cfg, section, "translation_speed_mps", translation_speed_mps, 1e-6, 10);
	rotation_wheel_speed_mps = readDouble(cfg, section, "rotation_wheel_speed_mps");
	requireInRange(cfg, section, "rotation_wheel_speed_mps", rotation_wheel_speed_mps, 1e-6, 10);
	encoder_ticks_per_m = readDouble(cfg, section, "encoder_ticks_per_m", encoder_ticks_per_m);
	requireInRange(cfg, section, "encoder_ticks_per_m", encoder_ticks_per_m, 1, 1e8);
	footprint_length_m = readDouble(cfg, section, "footprint_length_m", footprint_length_m);
	requireInRange(cfg, section, "footprint_length_m", footprint_length_m, 0.05, 5);
	footprint_width_m = readDouble(cfg, section, "footprint_width_m", footprint_width_m);
	requireInRange(cfg, section, "footprint_width_m", footprint_width_m, 0.05, 5);
	deck_height_m = readDouble(cfg, section, "deck_height_m", deck_height_m);
	requireInRange(cfg, section, "deck_height_m", deck_height_m, 0.01, 3);
	mast_half_width_m = readDouble(cfg, section, "mast_half_width_m", mast_half_width_m);
	requireInRange(cfg, section, "mast_half_width_m", mast_half_width_m, 0, 1);
	mast_top_height_m = readDouble(cfg, section, "mast_top_height_m", mast_top_height_m);
	requireInRange(cfg, section, "mast_top_height_m", mast_top_height_m, deck_height_m, 5);
}

void LabmateOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[labmate]\nwheel_half_separation_m  = " << wheel_half_separation_m
	    << "\nvelocity_noise_fraction  = " << velocity_noise_fraction
	    << "\ntranslation_speed_mps    = " << translation_speed_mps
	    << "\nrotation_wheel_speed_mps = " << rotation_wheel_speed_mps
	    << "\nencoder_ticks_per_m      = " << encoder_ticks_per_m
	    << "\nfootprint_length_m       = " << footprint_length_m
	    << "\nfootprint_width_m        = " << footprint_width_m
	    << "\ndeck_height_m            = " << deck_height_m
	    << "\nmast_half_width_m        = " << mast_half_width_m
	    << "\nmast_top_height_m        = " << mast_top_height_m << "\n";
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
