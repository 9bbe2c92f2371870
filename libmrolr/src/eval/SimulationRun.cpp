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
	    : m_world(w), m_setup(s), m_model(s.labmate), m_truth(w, s, seed), m_filter(s.slam, m_model)
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

	const world::World& m_world;
	const SimulationSetup& m_setup;
	base::LabmateModel m_model;
	detail::SimulatedWorld m_truth;
	slam::ActiveSlamFilter m_filter;
	Eigen::Vector3d m_dr = Eigen::Vector3d::Zero();
	std::string m_tracked;                             ///< label of the feature being tracked
	Eigen::Vector3d m_head = Eigen::Vector3d::Zero();  ///< ideal-head angles now
	std::vector<std::pair<std::string, Eigen::Vector3d>> m_step_measurements;
	int m_step_accepted = 0;
	RunResult m_r;
};

RunResult RunEngine::run()
{
	if (m_world.waypoints.size() < 2)
		throw std::invalid_argument(m_world.path + ": the route needs at least two waypoints");
	const auto t0 = std::chrono::steady_clock::now();
	const Eigen::Vector3d start = poseOf(m_world.waypoints.front());
	m_filter.reset(start);
	m_truth.setPose(start);
	m_dr = start;
	for (const auto& lm : m_world.landmarks)
		if (lm.known) m_filter.addKnownFeature(lm.name, lm.p_LinW);
	for (int lap = 0; lap < m_setup.sim.laps; ++lap)
		for (size_t w = 1; w < m_world.waypoints.size(); ++w)
		{
			const auto plan = base::planLeg(m_filter.vehicle(), poseOf(m_world.waypoints[w]),
			                                m_model, m_setup.trajectory);
			for (size_t k = 0; k < plan.size(); ++k) step(plan, k);
		}
	finish();
	m_r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return m_r;
}

void RunEngine::step(const std::vector<base::PlannedStep>& plan, size_t k)
{
	const auto& u = plan[k].u;
	m_truth.move(u);
	m_dr = m_model.move(m_dr, u);
	m_filter.predict(u);
	m_r.controls_odometry.emplace_back(u.v1_mps, u.v2_mps, u.dt_s);
	m_step_measurements.clear();
	m_step_accepted = 0;
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
	for (size_t i = 0; i < m_filter.numFeatures(); ++i)
		if (m_filter.info(i).label == label) return i;
	return std::nullopt;
}

std::vector<size_t> RunEngine::predictedVisible()
{
	std::vector<size_t> out;
	const Eigen::Vector3d xv = m_filter.vehicle();
	for (size_t i = 0; i < m_filter.numFeatures(); ++i)
	{
		const auto& info = m_filter.info(i);
		const Eigen::Vector3d y = m_filter.feature(i);
		const auto v = info.known ? slam::headCanFixate(xv, y, m_setup.slam.head)
		                          : slam::assessVisibility(xv, y, info.p_C0atInitInW, m_setup.slam);
		if (v == slam::Visibility::Visible) out.push_back(i);
	}
	return out;
}

void RunEngine::acquireFeatures()
{
	// 5.7: fewer than min_visible_features visible → search left, ahead, right for new ones.
	const double k = M_PI / 180,
	             dirs[3] = {m_setup.sim.search_pan_deg, 0, -m_setup.sim.search_pan_deg};
	for (double dir_deg : dirs)
	{
		if (static_cast<int>(predictedVisible().size()) >= m_setup.slam.min_visible_features)
			return;
		std::optional<size_t> best;
		double best_off = m_setup.sim.search_window_deg * k;
		for (size_t l = 0; l < m_world.landmarks.size(); ++l)
		{
			if (featureIndex(m_world.landmarks[l].name) || !m_truth.visible(l)) continue;
			const double off = std::abs(m_truth.trueAngles(l)[0] - dir_deg * k);
			if (off <= best_off) best = l, best_off = off;
		}
		if (!best) continue;
		bool outlier = false;
		const Eigen::Vector3d h = m_truth.measure(*best, false, outlier);
		m_filter.initialiseFeature(m_world.landmarks[*best].name, h);
		m_truth.markFirstSeen(*best);
		++m_r.features_added;
	}
}

std::vector<size_t> RunEngine::chooseFeatures(const std::vector<base::PlannedStep>& plan, size_t k)
{
	slam::SaccadeQuery q;
	q.visible = predictedVisible();
	if (q.visible.empty() || m_setup.sim.measurements_per_step == 0) return {};
	q.x = m_filter.stateVector();
	q.P = m_filter.covariance();
	q.current = featureIndex(m_tracked);
	q.head_angles = m_head;
	for (size_t j = k + 1; j < plan.size(); ++j) q.upcoming.push_back(plan[j].u);
	const auto d = slam::decideSaccade(q, m_setup.slam, m_model);
	std::vector<size_t> chosen{*d.feature};
	std::vector<size_t> rest;
	for (size_t i : q.visible)
		if (i != *d.feature) rest.push_back(i);
	while (static_cast<int>(chosen.size()) < m_setup.sim.measurements_per_step && !rest.empty())
	{
		const size_t b = *slam::largestVolume(q.x, q.P, rest, m_setup.slam);
		chosen.push_back(rest[b]);
		rest.erase(rest.begin() + static_cast<long>(b));
	}
	return chosen;
}

void RunEngine::measure(const std::vector<base::PlannedStep>& plan, size_t k)
{
	std::vector<slam::Observation> obs;
	std::vector<bool> outlier_of(m_filter.numFeatures(), false);
	for (size_t i : chooseFeatures(plan, k))
	{
		const size_t l = m_truth.landmarkIndex(m_filter.info(i).label);
		m_head = m_filter.predictedMeasurement(i);
		if (!m_truth.visible(l))
		{
			m_filter.recordAttempt(i, false);  // not found where predicted
			++m_r.attempts_failed;
			continue;
		}
		bool outlier = false;
		obs.push_back({i, m_truth.measure(l, true, outlier)});
		outlier_of[i] = outlier;
		m_r.outliers_injected += outlier ? 1 : 0;
	}
	if (!obs.empty()) m_tracked = m_filter.info(obs.front().feature).label;
	applyReport(m_filter.update(obs), outlier_of);
	for (const auto& o : obs) m_step_measurements.emplace_back(m_filter.info(o.feature).label, o.h);
}

void RunEngine::applyReport(const slam::UpdateReport& r, const std::vector<bool>& outlier_of)
{
	for (size_t i : r.accepted) m_filter.recordAttempt(i, true);
	for (size_t i : r.rejected)
	{
		m_filter.recordAttempt(i, false);
		++m_r.measurements_rejected;
		m_r.outliers_rejected += outlier_of[i] ? 1 : 0;
		++m_r.attempts_failed;
	}
	m_r.nis.insert(m_r.nis.end(), r.nis.begin(), r.nis.end());
	m_step_accepted = static_cast<int>(r.accepted.size());
}

void RunEngine::deleteFeatures()
{
	for (size_t i = m_filter.numFeatures(); i-- > 0;)
		if (!m_filter.info(i).known && m_filter.shouldDelete(i))
		{
			m_filter.deleteFeature(i);
			++m_r.features_deleted;
		}
}

void RunEngine::record()
{
	StepRecord s;
	s.truth = m_truth.pose();
	s.estimate = m_filter.vehicle();
	s.dead_reckoning = m_dr;
	s.P_vv = m_filter.vehicleCovariance();
	Eigen::Vector3d e = s.truth - s.estimate;
	e[2] = base::wrapAngle(e[2]);
	const Eigen::LDLT<Eigen::Matrix3d> ldlt(s.P_vv);
	// Right after the first straight step Q has rank 2 and NEES is undefined.
	s.nees = s.P_vv.determinant() > 1e-30 ? e.dot(ldlt.solve(e)) : std::nan("");
	s.features = static_cast<int>(m_filter.numFeatures());
	s.measured = m_step_accepted;
	m_r.steps.push_back(s);
	m_r.measurements.push_back(m_step_measurements);
}

void RunEngine::finish()
{
	for (size_t i = 0; i < m_filter.numFeatures(); ++i)
	{
		const auto& info = m_filter.info(i);
		m_r.final_labels.push_back(info.label);
		m_r.final_positions.push_back(m_filter.feature(i));
		m_r.final_covariances.push_back(m_filter.featureCovariance(i));
		if (info.known) continue;
		const auto& p = m_world.landmarks[m_truth.landmarkIndex(info.label)].p_LinW;
		m_r.landmark_error_sum_m += (m_filter.feature(i) - p).norm();
		++m_r.landmark_count;
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
