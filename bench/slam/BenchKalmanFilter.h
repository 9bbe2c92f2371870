#pragma once
// A minimal filter on MRPT's CKalmanFilterCapable<3,3,3,2> with MROLR's models (Labmate motion,
// ideal-head measurement), so the benchmark measures MRPT's own kfEKFNaive and kfEKFAlaDavison
// updates: one runOneKalmanIteration = prediction + measurement of one feature, no gating.

#include "BenchProblem.h"

#include <mrpt/bayes/CKalmanFilterCapable.h>

namespace mrolr::bench
{
class BenchKalmanFilter : public mrpt::bayes::CKalmanFilterCapable<3, 3, 3, 2>
{
 public:
	BenchKalmanFilter(BenchProblem& problem, mrpt::bayes::TKFMethod method);

	/** Predict with the problem's control, then measure feature @p feature. */
	void step(size_t feature);

 protected:
	void OnGetAction(KFArray_ACT& out_u) const override;
	void OnTransitionModel(const KFArray_ACT& u, KFArray_VEH& x, bool& skip) const override;
	void OnTransitionJacobian(KFMatrix_VxV& F) const override;
	void OnTransitionNoise(KFMatrix_VxV& Q) const override;
	void OnPreComputingPredictions(const vector_KFArray_OBS& all,
	                               std::vector<size_t>& out_idx) const override;
	void OnGetObservationNoise(KFMatrix_OxO& R) const override;
	void OnGetObservationsAndDataAssociation(vector_KFArray_OBS& out_z, std::vector<int>& out_da,
	                                         const vector_KFArray_OBS& predictions,
	                                         const KFMatrix& S, const std::vector<size_t>& idx_in_S,
	                                         const KFMatrix_OxO& R) override;
	void OnObservationModel(const std::vector<size_t>& idx, vector_KFArray_OBS& out) const override;
	void OnObservationJacobians(size_t idx, KFMatrix_OxV& Hx, KFMatrix_OxF& Hy) const override;
	void OnSubstractObservationVectors(KFArray_OBS& A, const KFArray_OBS& B) const override;

 private:
	Eigen::Vector3d vehicle() const { return {m_xkk[0], m_xkk[1], m_xkk[2]}; }
	Eigen::Vector3d feature(size_t i) const;

	BenchProblem& problem_;
	size_t feature_ = 0;
};

}  // namespace mrolr::bench
