#pragma once
/** Which feature to measure (thesis 5.7, 7.2 and appendix C "Choice of Feature").
 *
 * Vs, the volume of the n-σ ellipsoid of the innovation covariance S in (pan, elevation, vergence)
 * space (eq 5.147): Vs = 4/3 π n³ √(λ1 λ2 λ3) = 4/3 π n³ √det S. The most uncertain feature
 * relative to the vehicle (largest Vs) is the most valuable to measure.
 *
 * The saccade decision of 5.7 steps 1–4: N_i measurements are lost while the head saccades to
 * feature i (from a head-speed model); for each candidate, the covariance that would exist after
 * N_max + 1 steps if the head saccaded to it now (and then measured it) is predicted, and the head
 * moves to the feature whose state has the lowest Vs(max), the largest Vs over the visible
 * features, unless the currently tracked feature is already the lowest. */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/slam/SlamOptions.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace mrolr::slam
{
/** Vs of eq 5.147 for innovation covariance @p S (rad³) at @p n_sigma. */
double innovationVolume(const Eigen::Matrix3d& S, double n_sigma);

/** S_i = H P Hᵀ + R for feature @p i of the full state (x, P) (eq 5.36). */
Eigen::Matrix3d innovationCovarianceOf(const Eigen::VectorXd& x, const Eigen::MatrixXd& P, size_t i,
                                       const SlamOptions& options);

/** Index (into @p candidates) of the candidate with the largest Vs; nullopt for none. */
std::optional<size_t> largestVolume(const Eigen::VectorXd& x, const Eigen::MatrixXd& P,
                                    const std::vector<size_t>& candidates,
                                    const SlamOptions& options);

/** Measurements lost while the head moves from angles @p h_from to @p h_to (5.7 step 1): the
 * slowest joint at head_speed_deg_per_s plus saccade_overhead_s, in units of step_time_s. */
int measurementsLostBySaccade(const Eigen::Vector3d& h_from, const Eigen::Vector3d& h_to,
                              const SlamOptions& options);

/** Inputs of the saccade decision. */
struct SaccadeQuery
{
	Eigen::VectorXd x;              ///< full state
	Eigen::MatrixXd P;              ///< full covariance
	std::vector<size_t> visible;    ///< features that could be measured (map indices)
	std::optional<size_t> current;  ///< feature being tracked, if any
	Eigen::Vector3d head_angles = Eigen::Vector3d::Zero();  ///< ideal-head angles now
	std::vector<base::WheelControl> upcoming;  ///< the next controls (the last one is repeated)
};

struct SaccadeDecision
{
	std::optional<size_t> feature;  ///< feature to measure next (map index)
	bool saccade = false;           ///< true when it differs from the current one
	int n_max = 0;                  ///< N_max of step 2
	std::vector<double> vs_max;     ///< Vs(max) per visible feature (step 4)
};

/** 5.7 steps 1–4 on a linearised covariance prediction. */
SaccadeDecision decideSaccade(const SaccadeQuery& query, const SlamOptions& options,
                              const base::LabmateModel& model);

}  // namespace mrolr::slam
