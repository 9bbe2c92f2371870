#pragma once
/** The Labmate differential-drive base (thesis 4.2.6, eqs 4.51–4.61 and 5.1–5.19).
 *
 * Vehicle state x_v = (z, x, φ) in the world frame W: z forward, x left (metres), φ the heading in
 * radians measured from z towards x. Control u = (v1, v2), the two wheel velocities in m/s, applied
 * for Δt seconds: v1 is the wheel on the right (outer when turning left, φ increasing), so
 *   θ = (v1 − v2) Δt / (2 D1)   (eq 5.1),   s = (v1 + v2) Δt / 2   (arc length, eq 4.53),
 * and the base moves along a circular arc of radius R = s / θ (eq 4.54):
 *   z' = z + s (cos φ · sinθ/θ − sin φ · (1 − cos θ)/θ)   (eq 5.4, R = s/θ)
 *   x' = x + s (sin φ · sinθ/θ + cos φ · (1 − cos θ)/θ)   (eq 5.6)
 *   φ' = φ + θ                                            (eq 5.7)
 * sinθ/θ and (1 − cos θ)/θ are evaluated by their Taylor series near θ = 0, so the straight-line
 * case (eqs 5.8–5.10, v1 = v2) is the smooth limit, not a special case; v1 = −v2 rotates in place.
 */

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>

#include <cmath>
#include <iosfwd>
#include <string>

namespace mrolr::base
{
/** One control step: wheel velocities (m/s) held for dt_s seconds. */
struct WheelControl
{
	double v1_mps = 0;  ///< right wheel (positive v1 − v2 turns left)
	double v2_mps = 0;  ///< left wheel
	double dt_s = 0;
};

/** Parameters of the base, section [labmate] of config/labmate.ini. */
struct LabmateOptions
{
	double wheel_half_separation_m = 0.30;   ///< D1, half the distance between the wheels
	double velocity_noise_fraction = 0.14;   ///< σ_i = fraction · |v_i| (eq 5.13)
	double translation_speed_mps = 0.10;     ///< wheel speed for straight moves (5.6.3)
	double rotation_wheel_speed_mps = 0.05;  ///< |v1| = |v2| for rotations in place
	/** Optional: wheel-encoder counts per metre of wheel travel (the odometry's calibration). */
	double encoder_ticks_per_m = 20000;
	/** Optional: the base's footprint, a rectangle centred on the axle, length along the heading
	 * and width (m), as measured once; turning in place sweeps a disc of half its diagonal. */
	double footprint_length_m = 0.8, footprint_width_m = 0.7;
	double turnRadius() const { return 0.5 * std::hypot(footprint_length_m, footprint_width_m); }
	/** Optional: the deck, the base's flat top over the whole footprint, this high above the
	 * floor (m): the arm's column stands on it and a retrieved object is put down on it. */
	double deck_height_m = 0.289;
	/** Optional: the head's mast, a square column on the axle centre from the deck up to
	 * mast_top_height_m (the head on it included), this half wide (m): the arm keeps clear. */
	double mast_half_width_m = 0.08;
	double mast_top_height_m = 1.15;

	/** Reads every key above; errors name file, section and key (mrolr::util::ConfigError). */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dumpToTextStream(std::ostream& out) const;
};

/** The motion model f_v(x_v, u), its Jacobians and its process noise Q (eqs 5.11–5.19). */
class LabmateModel
{
 public:
	explicit LabmateModel(const LabmateOptions& options = {});

	const LabmateOptions& options() const { return options_; }

	/** f_v(x_v, u): the pose after the step (eqs 5.4–5.7); φ is not wrapped. */
	Eigen::Vector3d move(const Eigen::Vector3d& x_v, const WheelControl& u) const;

	/** ∂f_v/∂x_v (eq 5.16), exact for arcs and straight lines. */
	Eigen::Matrix3d jacobianState(const Eigen::Vector3d& x_v, const WheelControl& u) const;

	/** ∂f_v/∂u, with u = (v1, v2) (eqs 5.13–5.15, 5.18). */
	Eigen::Matrix<double, 3, 2> jacobianControl(const Eigen::Vector3d& x_v,
	                                            const WheelControl& u) const;

	/** U = diag(σ1², σ2²), σ_i = velocity_noise_fraction · |v_i| (eq 5.13), in (m/s)². */
	Eigen::Matrix2d controlCovariance(const WheelControl& u) const;

	/** Q = ∇f_u U ∇f_uᵀ (eq 5.12). */
	Eigen::Matrix3d processNoise(const Eigen::Vector3d& x_v, const WheelControl& u) const;

	/** Turn angle θ (rad) and arc length s (m) of a control (eqs 5.1, 4.53). */
	double turnAngle(const WheelControl& u) const;
	static double arcLength(const WheelControl& u) { return 0.5 * (u.v1_mps + u.v2_mps) * u.dt_s; }

	/** The control that rotates in place by @p angle_rad (positive towards x) at the configured
	 * rotation wheel speed. */
	WheelControl rotationControl(double angle_rad) const;
	/** The control that translates straight by @p distance_m (negative: backwards). */
	WheelControl translationControl(double distance_m) const;

 private:
	LabmateOptions options_;
};

}  // namespace mrolr::base
