#include "BenchKalmanFilter.h"

namespace mrolr::bench
{
BenchKalmanFilter::BenchKalmanFilter(BenchProblem& problem, mrpt::bayes::TKFMethod method)
    : problem_(problem)
{
	KF_options.method = method;
	m_xkk.resize(problem.x0.size());
	m_xkk.asEigen() = problem.x0;
	m_pkk.setSize(problem.P0.rows(), problem.P0.cols());
	m_pkk.asEigen() = problem.P0;
}

void BenchKalmanFilter::step(size_t feature)
{
	feature_ = feature;
	runOneKalmanIteration();
}

Eigen::Vector3d BenchKalmanFilter::feature(size_t i) const
{
	const size_t o = 3 + 3 * i;
	return {m_xkk[o], m_xkk[o + 1], m_xkk[o + 2]};
}

void BenchKalmanFilter::OnGetAction(KFArray_ACT& u) const
{
	const base::WheelControl c = problem_.control();
	u[0] = c.v1_mps;
	u[1] = c.v2_mps;
}

void BenchKalmanFilter::OnTransitionModel(const KFArray_ACT& u, KFArray_VEH& x, bool& skip) const
{
	skip = false;
	const Eigen::Vector3d xn = problem_.model.move(x.asEigen(), {u[0], u[1], 1.0});
	for (int k = 0; k < 3; ++k) x[k] = xn[k];
}

void BenchKalmanFilter::OnTransitionJacobian(KFMatrix_VxV& F) const
{
	F.asEigen() = problem_.model.jacobianState(vehicle(), problem_.control());
}

void BenchKalmanFilter::OnTransitionNoise(KFMatrix_VxV& Q) const
{
	Q.asEigen() = problem_.model.processNoise(vehicle(), problem_.control());
}

void BenchKalmanFilter::OnPreComputingPredictions(const vector_KFArray_OBS&,
                                                  std::vector<size_t>& out_idx) const
{
	out_idx.assign(1, feature_);
}

void BenchKalmanFilter::OnGetObservationNoise(KFMatrix_OxO& R) const
{
	R.asEigen() = problem_.R;
}

void BenchKalmanFilter::OnGetObservationsAndDataAssociation(
    vector_KFArray_OBS& out_z, std::vector<int>& out_da, const vector_KFArray_OBS&, const KFMatrix&,
    const std::vector<size_t>&, const KFMatrix_OxO&)
{
	const Eigen::Vector3d z = problem_.measure(vehicle(), feature(feature_));
	out_z.assign(1, KFArray_OBS(z));
	out_da.assign(1, static_cast<int>(feature_));
}

void BenchKalmanFilter::OnObservationModel(const std::vector<size_t>& idx,
                                           vector_KFArray_OBS& out) const
{
	out.resize(idx.size());
	for (size_t k = 0; k < idx.size(); ++k)
		out[k] = KFArray_OBS(slam::predictMeasurement(vehicle(), feature(idx[k]), problem_.head));
}

void BenchKalmanFilter::OnObservationJacobians(size_t idx, KFMatrix_OxV& Hx, KFMatrix_OxF& Hy) const
{
	const auto J = slam::measurementJacobians(vehicle(), feature(idx), problem_.head);
	Hx.asEigen() = J.H_xv;
	Hy.asEigen() = J.H_y;
}

void BenchKalmanFilter::OnSubstractObservationVectors(KFArray_OBS& A, const KFArray_OBS& B) const
{
	A = KFArray_OBS(slam::measurementDifference(A.asEigen(), B.asEigen()));
}

}  // namespace mrolr::bench
