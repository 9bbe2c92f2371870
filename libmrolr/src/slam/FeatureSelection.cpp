#include <mrolr/slam/FeatureSelection.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace mrolr::slam
{
namespace
{
Eigen::Matrix3d noiseOf(const SlamOptions& o)
{
	return Eigen::Vector3d(o.std_pan_rad, o.std_elevation_rad, o.std_vergence_rad)
	    .cwiseAbs2()
	    .asDiagonal();
}

/** The 3 × n measurement Jacobian of feature i in the full state. */
Eigen::MatrixXd fullJacobian(const Eigen::VectorXd& x, size_t i, const SlamOptions& o)
{
	const auto o_i = static_cast<Eigen::Index>(3 + 3 * i);
	const auto J = measurementJacobians(x.head<3>(), x.segment<3>(o_i), o.head.constants);
	Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3, x.size());
	H.leftCols<3>() = J.H_xv;
	H.block<3, 3>(0, o_i) = J.H_y;
	return H;
}

/** Covariance prediction for one control (eq 5.33); the mean follows the model. */
void predictCovariance(Eigen::VectorXd& x, Eigen::MatrixXd& P, const base::WheelControl& u,
                       const base::LabmateModel& model)
{
	const Eigen::Vector3d xv = x.head<3>();
	const Eigen::Matrix3d F = model.jacobianState(xv, u);
	P.topRows<3>() = (F * P.topRows<3>()).eval();
	P.leftCols<3>() = (P.leftCols<3>() * F.transpose()).eval();
	P.topLeftCorner<3, 3>() += model.processNoise(xv, u);
	x.head<3>() = model.move(xv, u);
}

/** Covariance after measuring feature i (the mean is expected not to move). */
void measureCovariance(const Eigen::VectorXd& x, Eigen::MatrixXd& P, size_t i, const SlamOptions& o)
{
	const Eigen::MatrixXd H = fullJacobian(x, i, o);
	const Eigen::MatrixXd PHt = P * H.transpose();
	const Eigen::Matrix3d S = H * PHt + noiseOf(o);
	P -= PHt * S.ldlt().solve(PHt.transpose());
	P = (0.5 * (P + P.transpose())).eval();
}

double largestVs(const Eigen::VectorXd& x, const Eigen::MatrixXd& P,
                 const std::vector<size_t>& visible, const SlamOptions& o)
{
	double vmax = 0;
	for (size_t j : visible)
		vmax = std::max(
		    vmax, innovationVolume(innovationCovarianceOf(x, P, j, o), o.innovation_volume_sigma));
	return vmax;
}

const base::WheelControl& controlAt(const std::vector<base::WheelControl>& u, int k)
{
	return u[std::min<size_t>(static_cast<size_t>(k), u.size() - 1)];
}
}  // namespace

double innovationVolume(const Eigen::Matrix3d& S, double n)
{
	return 4.0 / 3.0 * M_PI * n * n * n * std::sqrt(std::max(S.determinant(), 0.0));
}

Eigen::Matrix3d innovationCovarianceOf(const Eigen::VectorXd& x, const Eigen::MatrixXd& P, size_t i,
                                       const SlamOptions& o)
{
	const Eigen::MatrixXd H = fullJacobian(x, i, o);
	return H * P * H.transpose() + noiseOf(o);
}

std::optional<size_t> largestVolume(const Eigen::VectorXd& x, const Eigen::MatrixXd& P,
                                    const std::vector<size_t>& candidates, const SlamOptions& o)
{
	std::optional<size_t> best;
	double vbest = -1;
	for (size_t k = 0; k < candidates.size(); ++k)
	{
		const double v = innovationVolume(innovationCovarianceOf(x, P, candidates[k], o), 1.0);
		if (v > vbest) best = k, vbest = v;
	}
	return best;
}

int measurementsLostBySaccade(const Eigen::Vector3d& h_from, const Eigen::Vector3d& h_to,
                              const SlamOptions& o)
{
	const double move_deg = (h_to - h_from).cwiseAbs().maxCoeff() * 180 / M_PI;
	const double t = move_deg / o.head_speed_deg_per_s + o.saccade_overhead_s;
	return static_cast<int>(std::ceil(t / o.step_time_s - 1e-12));
}

SaccadeDecision decideSaccade(const SaccadeQuery& q, const SlamOptions& o,
                              const base::LabmateModel& model)
{
	SaccadeDecision d;
	if (q.visible.empty()) return d;
	const std::vector<base::WheelControl> upcoming =
	    q.upcoming.empty() ? std::vector<base::WheelControl>{base::WheelControl{}} : q.upcoming;
	// Steps 1–2: measurements lost by each saccade, and the largest.
	std::vector<int> lost;
	for (size_t i : q.visible)
	{
		const Eigen::Vector3d h = predictMeasurement(
		    q.x.head<3>(), q.x.segment<3>(static_cast<Eigen::Index>(3 + 3 * i)), o.head.constants);
		lost.push_back(q.current == i ? 0 : measurementsLostBySaccade(q.head_angles, h, o));
	}
	d.n_max = *std::max_element(lost.begin(), lost.end());
	// Steps 3–4: the state after N_max + 1 steps for each choice, and its Vs(max).
	size_t best = 0;
	for (size_t k = 0; k < q.visible.size(); ++k)
	{
		Eigen::VectorXd x = q.x;
		Eigen::MatrixXd P = q.P;
		for (int s = 0; s <= d.n_max; ++s)
		{
			predictCovariance(x, P, controlAt(upcoming, s), model);
			if (s >= lost[k]) measureCovariance(x, P, q.visible[k], o);
		}
		d.vs_max.push_back(largestVs(x, P, q.visible, o));
		if (d.vs_max[k] < d.vs_max[best]) best = k;
	}
	// Stay with the current feature when it is (one of) the lowest.
	for (size_t k = 0; k < q.visible.size(); ++k)
		if (q.current == q.visible[k] && d.vs_max[k] <= d.vs_max[best]) best = k;
	d.feature = q.visible[best];
	d.saccade = q.current != d.feature;
	return d;
}

}  // namespace mrolr::slam
