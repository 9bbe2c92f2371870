#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/slam/ActiveSlamFilter.h>

#include <mrolr/slam/Chi2.h>
#include <mrolr/slam/ProcessNoise.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <stdexcept>

namespace mrolr::slam
{
ActiveSlamFilter::ActiveSlamFilter(const SlamOptions& options, const base::LabmateModel& model)
    : options_(options), model_(model)
{
	gate_ = chi2Quantile(options.gate_probability, 3);
	KF_options.use_analytic_observation_jacobian = true;
	KF_options.use_analytic_transition_jacobian = true;
	// MRPT runs the predictions and the batch update; sequential and postponed updates are ours.
	KF_options.method = mrpt::bayes::kfEKFNaive;
	reset();
}

void ActiveSlamFilter::predict(const base::WheelControl& u)
{
	u_ = u;
	if (tracker_.tracking())
	{
		predictPostponed();
		return;
	}
	pending_.clear();
	skip_prediction_ = false;
	runOneKalmanIteration();
	notePrediction(vehicleRaw());
}

UpdateReport ActiveSlamFilter::update(const std::vector<Observation>& z)
{
	for (size_t a = 0; a < z.size(); ++a)
	{
		if (z[a].feature >= info_.size())
			throw std::out_of_range("ActiveSlamFilter::update: no feature " +
			                        std::to_string(z[a].feature));
		for (size_t b = a + 1; b < z.size(); ++b)
			if (z[a].feature == z[b].feature)
				throw std::invalid_argument("ActiveSlamFilter::update: feature measured twice");
	}
	if (postponedApplies(z)) return updatePostponed(z.front());
	synchronise();
	report_ = {};
	if (z.empty()) return report_;
	if (options_.update_method == UpdateMethod::Sequential)
	{
		updateSequential(z);
		return report_;
	}
	pending_ = z;
	skip_prediction_ = true;
	runOneKalmanIteration();
	pending_.clear();
	return report_;
}

void ActiveSlamFilter::OnGetAction(KFArray_ACT& u) const
{
	u[0] = u_.v1_mps;
	u[1] = u_.v2_mps;
}

void ActiveSlamFilter::OnTransitionModel(const KFArray_ACT& u, KFArray_VEH& x, bool& skip) const
{
	skip = skip_prediction_;
	const Eigen::Vector3d xn = model_.move(x.asEigen(), {u[0], u[1], u_.dt_s});
	for (int k = 0; k < 3; ++k) x[k] = xn[k];
}

void ActiveSlamFilter::OnTransitionJacobian(KFMatrix_VxV& F) const
{
	F.asEigen() = transitionJacobian(vehicleRaw());
}

void ActiveSlamFilter::OnTransitionNoise(KFMatrix_VxV& Q) const
{
	Q.asEigen() = processNoise(vehicleRaw());
}

Eigen::Matrix3d ActiveSlamFilter::processNoise(const Eigen::Vector3d& x_v) const
{
	// Q of the model (eq 5.12) has rank 2 (two wheels drive three states); the floor stands for
	// what its first-order propagation leaves out, scaled by the time the step takes.
	const double t = std::abs(u_.dt_s);
	const Eigen::Vector3d floor(options_.process_noise_floor_m, options_.process_noise_floor_m,
	                            options_.process_noise_floor_rad);
	Eigen::Matrix3d Q =
	    model_.processNoise(x_v, u_) + (t * floor.cwiseAbs2()).asDiagonal().toDenseMatrix();
	if (options_.process_noise_order == 2) Q += secondOrderProcessNoise(model_, x_v, u_);
	return Q;
}

void ActiveSlamFilter::OnPreComputingPredictions(const vector_KFArray_OBS&,
                                                 std::vector<size_t>& out_idx) const
{
	// Only the features being measured: the head looks at one feature at a time.
	out_idx.clear();
	for (const auto& o : pending_) out_idx.push_back(o.feature);
}

void ActiveSlamFilter::OnGetObservationNoise(KFMatrix_OxO& R) const
{
	R.asEigen() = measurementNoise();
}

Eigen::Matrix3d ActiveSlamFilter::measurementNoise() const
{
	const Eigen::Vector3d s(options_.std_pan_rad, options_.std_elevation_rad,
	                        options_.std_vergence_rad);
	return s.cwiseAbs2().asDiagonal();
}

void ActiveSlamFilter::OnGetObservationsAndDataAssociation(
    vector_KFArray_OBS& out_z, std::vector<int>& out_da, const vector_KFArray_OBS& predictions,
    const KFMatrix& S, const std::vector<size_t>& idx_in_S, const KFMatrix_OxO&)
{
	out_z.clear();
	out_da.clear();
	for (const auto& o : pending_)
	{
		const auto j = std::find(idx_in_S.begin(), idx_in_S.end(), o.feature) - idx_in_S.begin();
		const Eigen::Matrix3d Si = S.asEigen().block<3, 3>(3 * j, 3 * j);
		const Eigen::Vector3d nu = measurementDifference(o.h, predictions[o.feature].asEigen());
		const double nis = nu.dot(Si.ldlt().solve(nu));
		if (!(nis <= gate_))
		{
			report_.rejected.push_back(o.feature);
			report_.rejected_nis.push_back(nis);
			continue;
		}
		report_.accepted.push_back(o.feature);
		report_.nis.push_back(nis);
		KFArray_OBS zz;
		for (int k = 0; k < 3; ++k) zz[k] = o.h[k];
		out_z.push_back(zz);
		out_da.push_back(static_cast<int>(o.feature));
	}
}

void ActiveSlamFilter::OnObservationModel(const std::vector<size_t>& idx,
                                          vector_KFArray_OBS& out) const
{
	out.resize(idx.size());
	const Eigen::Vector3d xv = vehicleRaw();
	for (size_t k = 0; k < idx.size(); ++k)
	{
		const Eigen::Vector3d h =
		    predictMeasurement(xv, featureRaw(idx[k]), options_.head.constants);
		for (int c = 0; c < 3; ++c) out[k][c] = h[c];
	}
}

void ActiveSlamFilter::OnObservationJacobians(size_t idx, KFMatrix_OxV& Hx, KFMatrix_OxF& Hy) const
{
	const auto J = observationJacobians(idx, vehicleRaw(), featureRaw(idx));
	Hx.asEigen() = J.H_xv;
	Hy.asEigen() = J.H_y;
}

void ActiveSlamFilter::OnSubstractObservationVectors(KFArray_OBS& A, const KFArray_OBS& B) const
{
	const Eigen::Vector3d d = measurementDifference(A.asEigen(), B.asEigen());
	for (int k = 0; k < 3; ++k) A[k] = d[k];
}

void ActiveSlamFilter::OnNormalizeStateVector()
{
	m_xkk[2] = base::wrapAngle(m_xkk[2]);
}

void ActiveSlamFilter::OnPostIteration()
{
	// Keep P exactly symmetric: MRPT's batch update (I − KH)P is not, in floating point.
	auto P = m_pkk.asEigen();
	const Eigen::MatrixXd Ps = 0.5 * (P + P.transpose());
	P = Ps;
}

Eigen::Vector3d ActiveSlamFilter::vehicleRaw() const
{
	return {m_xkk[0], m_xkk[1], m_xkk[2]};
}

Eigen::Vector3d ActiveSlamFilter::featureRaw(size_t i) const
{
	const size_t o = 3 + 3 * i;
	return {m_xkk[o], m_xkk[o + 1], m_xkk[o + 2]};
}

}  // namespace mrolr::slam
