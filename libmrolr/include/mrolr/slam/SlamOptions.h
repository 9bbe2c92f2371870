#pragma once
/** Options of the active-vision EKF-SLAM filter (thesis 5.5–5.7). The head constants and joint
 * limits are read from the head's own section ([bisight] of config/bisight.ini) so that they are
 * written once; everything else from the filter's section ([slam] of config/ekf_sim.ini). */

#include <mrolr/slam/HeadMeasurement.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::slam
{
/** How measurements update the filter. */
enum class UpdateMethod
{
	Sequential,  ///< one scalar component at a time (eqs 5.42–5.45; FilterSequential.cpp)
	Batch,       ///< all components at once (MRPT kfEKFNaive)
	Postponed    ///< Davison's postponed update while one feature is tracked (appendix C)
};

/** "sequential" | "batch" | "postponed", as the key update_method names it. */
std::string toString(UpdateMethod method);

/** Where the filter evaluates its Jacobians. */
enum class JacobianPoint
{
	Standard,      ///< at the current estimate (the thesis's EKF)
	FirstEstimate  ///< FEJ-EKF (Huang, Mourikis & Roumeliotis 2008): motion Jacobians from the
	               ///< propagated estimates, measurement Jacobians at each feature's first estimate
};

/** "standard" | "first_estimate", as the key jacobians names it. */
std::string toString(JacobianPoint point);

/** Head constants and joint limits, from the head's section (keys as in config/bisight.ini). */
struct HeadModelOptions
{
	HeadConstants constants;
	double pan_limit_deg = 90;       ///< |pan| allowed
	double tilt_limit_deg = 45;      ///< |elevation| allowed
	double vergence_limit_deg = 40;  ///< vergence allowed (limits how near a feature may be)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dumpToTextStream(std::ostream& out) const;
};

/** The filter's own options (section [slam]). */
struct SlamOptions
{
	HeadModelOptions head;
	/** Measurement noise R = diag(σ²) in angle space (eq 5.41); the thesis's sample run uses
	 * R = diag(4e-6, 1e-4, 4e-6) rad², i.e. σ = 0.002, 0.01, 0.002 rad. */
	double std_pan_rad = 0.002;
	double std_elevation_rad = 0.01;
	double std_vergence_rad = 0.002;
	UpdateMethod update_method = UpdateMethod::Sequential;
	/** Optional key `jacobians` (default standard): first_estimate for FEJ-EKF. */
	JacobianPoint jacobians = JacobianPoint::Standard;
	/** Optional key `process_noise_order` (default 1): 1 = Q = ∇f_u U ∇f_uᵀ (eq 5.12); 2 adds the
	 * second-order term ½ tr(H_a U H_b U) of the wheel noise (slam/ProcessNoise.h). */
	int process_noise_order = 1;
	/** Added to the model's Q per second of motion: σ² = floor² · Δt for z, x (m) and φ (rad). */
	double process_noise_floor_m = 0;
	double process_noise_floor_rad = 0;
	/** A measurement whose NIS exceeds the χ²₃ quantile of this probability is rejected. */
	double gate_probability = 0.99;
	/** Feature management (5.7). */
	int min_visible_features = 2;
	int attempt_window = 10;  ///< delete when more than half of the last N attempts failed
	double visibility_ratio_min = 0.7;  ///< current / initial viewing distance (5.2.1)
	double visibility_ratio_max = 1.4;
	double max_view_change_deg = 45;  ///< change of viewing direction since initialisation
	/** Selection (5.7, eq 5.147): Vs is the volume of the n-σ innovation ellipsoid. */
	double innovation_volume_sigma = 3;
	/** Saccade model (5.7 step 1): head speed and the time between measurements. */
	double head_speed_deg_per_s = 60;
	double saccade_overhead_s = 0.2;  ///< settling and search time per saccade
	double step_time_s = 1.0;         ///< time from one measurement to the next while tracking

	/** Reads the [slam] keys from @p section (the head is loaded separately into #head). */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dumpToTextStream(std::ostream& out) const;
};

}  // namespace mrolr::slam
