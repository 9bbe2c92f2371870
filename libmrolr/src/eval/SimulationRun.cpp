// One simulation run: drive the route, keep the map (5.7), measure, update, record.
#include "SimulatedWorld.h"

#include <mrolr/slam/ActiveSlamFilter.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>

#include <Eigen/Cholesky>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace mrolr::eval
{
namespace
{
Eigen::Vector3d poseOf(const world::Waypoint& w)
{
	return {w.z_m, w.x_m, w.phi_rad};
}

class RunEngine
{
 public:
	RunEngine(const world::World& w, const SimulationSetup& s, uint64_t seed)
	    : world_(w), setup_(s), model_(s.labmate), truth_(w, s, seed), filter_(s.slam, model_)
	{
	}

	RunResult run();

 private:
	void step(const std::vector<base::PlannedStep>& plan, size_t k);
	std::vector<size_t> predictedVisible();
	void acquireFeatures();
	void measure(const std::vector<base::PlannedStep>& plan, size_t k);
	std::vector<size_t> chooseFeatures(const std::vector<base::PlannedStep>& plan, size_t k);
	void applyReport(const slam::UpdateReport& r, const std::vector<bool>& outlier_of_feature);
	void deleteFeatures();
	void record();
	void finish();
	std::optional<size_t> featureIndex(const std::string& label);

	const world::World& world_;
	const SimulationSetup& setup_;
	base::LabmateModel model_;
	detail::SimulatedWorld truth_;
	slam::ActiveSlamFilter filter_;
	Eigen::Vector3d dr_ = Eigen::Vector3d::Zero();
	std::string tracked_;                             ///< label of the feature being tracked
	Eigen::Vector3d head_ = Eigen::Vector3d::Zero();  ///< ideal-head angles now
	std::vector<std::pair<std::string, Eigen::Vector3d>> step_measurements_;
	int step_accepted_ = 0;
	RunResult r_;
};

RunResult RunEngine::run()
{
	if (world_.waypoints.size() < 2)
		throw std::invalid_argument(world_.path + ": the route needs at least two waypoints");
	const auto t0 = std::chrono::steady_clock::now();
	const Eigen::Vector3d start = poseOf(world_.waypoints.front());
	filter_.reset(start);
	truth_.setPose(start);
	dr_ = start;
	for (const auto& lm : world_.landmarks)
		if (lm.known) filter_.addKnownFeature(lm.name, lm.p_LinW);
	for (int lap = 0; lap < setup_.sim.laps; ++lap)
		for (size_t w = 1; w < world_.waypoints.size(); ++w)
		{
			const auto plan = base::planLeg(filter_.vehicle(), poseOf(world_.waypoints[w]),
			                                model_, setup_.trajectory);
			for (size_t k = 0; k < plan.size(); ++k) step(plan, k);
		}
	finish();
	r_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return r_;
}

void RunEngine::step(const std::vector<base::PlannedStep>& plan, size_t k)
{
	const auto& u = plan[k].u;
	truth_.move(u);
	dr_ = model_.move(dr_, u);
	filter_.predict(u);
	r_.controls_odometry.emplace_back(u.v1_mps, u.v2_mps, u.dt_s);
	step_measurements_.clear();
	step_accepted_ = 0;
	// Measure the mapped features first, then add new ones (5.7) from the updated pose: initialised
	// from the prior, right after the step's 3.8° (straight) or 9° (90° turn) of heading noise, a
	// feature 5 m away inherits a lateral spread of 0.3–0.8 m tied to the heading by a rotation the
	// linearisation of eq 5.48 bends into a line, and the map turns over-confident (docs/slam.md).
	measure(plan, k);
	acquireFeatures();
	deleteFeatures();
	record();
}

std::optional<size_t> RunEngine::featureIndex(const std::string& label)
{
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
		if (filter_.info(i).label == label) return i;
	return std::nullopt;
}

std::vector<size_t> RunEngine::predictedVisible()
{
	std::vector<size_t> out;
	const Eigen::Vector3d xv = filter_.vehicle();
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
	{
		const auto& info = filter_.info(i);
		const Eigen::Vector3d y = filter_.feature(i);
		const auto v = info.known ? slam::headCanFixate(xv, y, setup_.slam.head)
		                          : slam::assessVisibility(xv, y, info.p_C0atInitInW, setup_.slam);
		if (v == slam::Visibility::Visible) out.push_back(i);
	}
	return out;
}

void RunEngine::acquireFeatures()
{
	// 5.7: fewer than min_visible_features visible → search left, ahead, right for new ones.
	const double k = M_PI / 180,
	             dirs[3] = {setup_.sim.search_pan_deg, 0, -setup_.sim.search_pan_deg};
	for (double dir_deg : dirs)
	{
		if (static_cast<int>(predictedVisible().size()) >= setup_.slam.min_visible_features)
			return;
		std::optional<size_t> best;
		double best_off = setup_.sim.search_window_deg * k;
		for (size_t l = 0; l < world_.landmarks.size(); ++l)
		{
			if (featureIndex(world_.landmarks[l].name) || !truth_.visible(l)) continue;
			const double off = std::abs(truth_.trueAngles(l)[0] - dir_deg * k);
			if (off <= best_off) best = l, best_off = off;
		}
		if (!best) continue;
		bool outlier = false;
		const Eigen::Vector3d h = truth_.measure(*best, false, outlier);
		filter_.initialiseFeature(world_.landmarks[*best].name, h);
		truth_.markFirstSeen(*best);
		++r_.features_added;
	}
}

std::vector<size_t> RunEngine::chooseFeatures(const std::vector<base::PlannedStep>& plan, size_t k)
{
	slam::SaccadeQuery q;
	q.visible = predictedVisible();
	if (q.visible.empty() || setup_.sim.measurements_per_step == 0) return {};
	q.x = filter_.stateVector();
	q.P = filter_.covariance();
	q.current = featureIndex(tracked_);
	q.head_angles = head_;
	for (size_t j = k + 1; j < plan.size(); ++j) q.upcoming.push_back(plan[j].u);
	const auto d = slam::decideSaccade(q, setup_.slam, model_);
	std::vector<size_t> chosen{*d.feature};
	std::vector<size_t> rest;
	for (size_t i : q.visible)
		if (i != *d.feature) rest.push_back(i);
	while (static_cast<int>(chosen.size()) < setup_.sim.measurements_per_step && !rest.empty())
	{
		const size_t b = *slam::largestVolume(q.x, q.P, rest, setup_.slam);
		chosen.push_back(rest[b]);
		rest.erase(rest.begin() + static_cast<long>(b));
	}
	return chosen;
}

void RunEngine::measure(const std::vector<base::PlannedStep>& plan, size_t k)
{
	std::vector<slam::Observation> obs;
	std::vector<bool> outlier_of(filter_.numFeatures(), false);
	for (size_t i : chooseFeatures(plan, k))
	{
		const size_t l = truth_.landmarkIndex(filter_.info(i).label);
		head_ = filter_.predictedMeasurement(i);
		if (!truth_.visible(l))
		{
			filter_.recordAttempt(i, false);  // not found where predicted
			++r_.attempts_failed;
			continue;
		}
		bool outlier = false;
		obs.push_back({i, truth_.measure(l, true, outlier)});
		outlier_of[i] = outlier;
		r_.outliers_injected += outlier ? 1 : 0;
	}
	if (!obs.empty()) tracked_ = filter_.info(obs.front().feature).label;
	applyReport(filter_.update(obs), outlier_of);
	for (const auto& o : obs) step_measurements_.emplace_back(filter_.info(o.feature).label, o.h);
}

void RunEngine::applyReport(const slam::UpdateReport& r, const std::vector<bool>& outlier_of)
{
	for (size_t i : r.accepted) filter_.recordAttempt(i, true);
	for (size_t i : r.rejected)
	{
		filter_.recordAttempt(i, false);
		++r_.measurements_rejected;
		r_.outliers_rejected += outlier_of[i] ? 1 : 0;
		++r_.attempts_failed;
	}
	r_.nis.insert(r_.nis.end(), r.nis.begin(), r.nis.end());
	step_accepted_ = static_cast<int>(r.accepted.size());
}

void RunEngine::deleteFeatures()
{
	for (size_t i = filter_.numFeatures(); i-- > 0;)
		if (!filter_.info(i).known && filter_.shouldDelete(i))
		{
			filter_.deleteFeature(i);
			++r_.features_deleted;
		}
}

void RunEngine::record()
{
	StepRecord s;
	s.truth = truth_.pose();
	s.estimate = filter_.vehicle();
	s.dead_reckoning = dr_;
	s.P_vv = filter_.vehicleCovariance();
	Eigen::Vector3d e = s.truth - s.estimate;
	e[2] = base::wrapAngle(e[2]);
	const Eigen::LDLT<Eigen::Matrix3d> ldlt(s.P_vv);
	// Right after the first straight step Q has rank 2 and NEES is undefined.
	s.nees = s.P_vv.determinant() > 1e-30 ? e.dot(ldlt.solve(e)) : std::nan("");
	s.features = static_cast<int>(filter_.numFeatures());
	s.measured = step_accepted_;
	r_.steps.push_back(s);
	r_.measurements.push_back(step_measurements_);
}

void RunEngine::finish()
{
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
	{
		const auto& info = filter_.info(i);
		r_.final_labels.push_back(info.label);
		r_.final_positions.push_back(filter_.feature(i));
		r_.final_covariances.push_back(filter_.featureCovariance(i));
		if (info.known) continue;
		const auto& p = world_.landmarks[truth_.landmarkIndex(info.label)].p_LinW;
		r_.landmark_error_sum_m += (filter_.feature(i) - p).norm();
		++r_.landmark_count;
	}
}
}  // namespace

RunResult runSimulation(const world::World& world, const SimulationSetup& setup, uint64_t seed)
{
	return RunEngine(world, setup, seed).run();
}

std::vector<RunResult> runMonteCarlo(const world::World& world, const SimulationSetup& setup,
                                     int runs, uint64_t seed0,
                                     const std::function<void(int done)>& after_run)
{
	std::vector<RunResult> out;
	for (int r = 0; r < runs; ++r)
	{
		out.push_back(runSimulation(world, setup, seed0 + 1000 * static_cast<uint64_t>(r)));
		if (after_run) after_run(r + 1);
	}
	return out;
}

}  // namespace mrolr::eval
