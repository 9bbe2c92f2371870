// Monte-Carlo figures: the mean vehicle NEES per step against its χ² bounds, and error statistics.
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/eval/EkfSimulation.h>
#include <mrolr/slam/Chi2.h>

#include <algorithm>
#include <cmath>

namespace mrolr::eval
{
namespace
{
double positionError(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	return (a - b).head<2>().norm();
}

void neesFigures(const std::vector<RunResult>& runs, MonteCarloSummary& s)
{
	// The sum over R runs of χ²₃ variables is χ²_{3R}: bounds of the mean are its quantiles / R.
	const unsigned dof = 3 * static_cast<unsigned>(s.runs);
	s.nees_lo = slam::chi2Quantile(0.025, dof) / s.runs;
	s.nees_hi = slam::chi2Quantile(0.975, dof) / s.runs;
	int inside = 0;
	for (int k = 0; k < s.steps; ++k)
	{
		double sum = 0;
		for (const auto& r : runs) sum += r.steps[static_cast<size_t>(k)].nees;
		s.mean_nees.push_back(sum / s.runs);
		if (!std::isfinite(s.mean_nees.back())) continue;  // undefined in some run
		++s.nees_steps;
		inside += (s.mean_nees.back() >= s.nees_lo && s.mean_nees.back() <= s.nees_hi) ? 1 : 0;
	}
	s.nees_inside_fraction = s.nees_steps > 0 ? static_cast<double>(inside) / s.nees_steps : 0;
}

void errorFigures(const std::vector<RunResult>& runs, MonteCarloSummary& s)
{
	double slam2 = 0, dr2 = 0, head2 = 0, nis = 0;
	long n = 0, n_nis = 0, landmarks = 0;
	double lm_sum = 0, seconds = 0;
	for (const auto& r : runs)
	{
		for (const auto& st : r.steps)
		{
			slam2 += std::pow(positionError(st.truth, st.estimate), 2);
			dr2 += std::pow(positionError(st.truth, st.dead_reckoning), 2);
			head2 += std::pow(base::wrapAngle(st.truth[2] - st.estimate[2]), 2);
			++n;
		}
		s.slam_final_position_error_m +=
		    positionError(r.steps.back().truth, r.steps.back().estimate);
		s.dr_final_position_error_m +=
		    positionError(r.steps.back().truth, r.steps.back().dead_reckoning);
		for (double v : r.nis) nis += v, ++n_nis;
		lm_sum += r.landmark_error_sum_m;
		landmarks += r.landmark_count;
		s.features_added += r.features_added;
		s.features_deleted += r.features_deleted;
		s.outliers_rejected += r.measurements_rejected;
		s.outliers_injected += r.outliers_injected;
		seconds += r.seconds;
	}
	s.slam_rms_position_m = std::sqrt(slam2 / n);
	s.dr_rms_position_m = std::sqrt(dr2 / n);
	s.slam_rms_heading_deg = std::sqrt(head2 / n) * 180 / M_PI;
	s.slam_final_position_error_m /= s.runs;
	s.dr_final_position_error_m /= s.runs;
	s.mean_nis = n_nis > 0 ? nis / n_nis : 0;
	s.mean_landmark_error_m = landmarks > 0 ? lm_sum / landmarks : 0;
	s.ms_per_step = 1e3 * seconds / n;
}
}  // namespace

MonteCarloSummary summarise(const std::vector<RunResult>& runs)
{
	MonteCarloSummary s;
	s.runs = static_cast<int>(runs.size());
	if (runs.empty()) return s;
	s.steps = static_cast<int>(runs.front().steps.size());
	for (const auto& r : runs) s.steps = std::min(s.steps, static_cast<int>(r.steps.size()));
	if (s.steps == 0) return s;
	neesFigures(runs, s);
	errorFigures(runs, s);
	return s;
}

}  // namespace mrolr::eval
