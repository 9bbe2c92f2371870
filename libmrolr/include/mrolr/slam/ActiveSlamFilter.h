#pragma once
/** Active-vision EKF-SLAM (thesis 5.4–5.7) on MRPT's Kalman-filter framework.
 *
 * State x = (x_v, y_1 … y_n): the vehicle (z, x, φ) in W and 3D point features (X, Y, Z) in W
 * (eqs 5.29–5.30); measurement h = (pan, elevation, vergence) of an ideal head at C0 (eq 5.40);
 * control u = (v1, v2) of the Labmate base (eq 5.11). Prediction uses the Labmate model with its
 * analytic Jacobian and Q (eqs 5.32–5.34); updates are sequential scalar (eqs 5.42–5.45, written
 * here because MRPT 2.5's kfEKFAlaDavison does not correct the later components' innovations for
 * the earlier ones), batch (MRPT's kfEKFNaive) or Davison's postponed update (appendix C), chosen
 * by SlamOptions::update_method. Every measurement is gated by its NIS; P is symmetrised after
 * every update (MRPT's batch update P ← (I − KH)P is not symmetric in floating point). */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/slam/PostponedTracker.h>
#include <mrolr/slam/SlamOptions.h>

#include <mrpt/bayes/CKalmanFilterCapable.h>

#include <Eigen/Core>

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::slam
{
/** Bookkeeping of one mapped feature, parallel to the state vector. */
struct FeatureInfo
{
	std::string label;
	bool known = false;  ///< known feature (5.6.2): initialised with zero covariance
	Eigen::Vector3d p_C0atInitInW = Eigen::Vector3d::Zero();  ///< head centre when first seen
	/** The feature's first estimate in W (m): where FEJ evaluates its measurement Jacobian. */
	Eigen::Vector3d p_FinW_first = Eigen::Vector3d::Zero();
	std::deque<bool> attempts;  ///< last measurement attempts, true = success (5.7)
	int successes = 0;
	int failures = 0;
};

/** One measurement of a mapped feature: index in the map and h = (pan, elevation, vergence). */
struct Observation
{
	size_t feature = 0;
	Eigen::Vector3d h = Eigen::Vector3d::Zero();
};

/** What an update did with each observation. */
struct UpdateReport
{
	std::vector<size_t> accepted;  ///< feature indices used to update the filter
	std::vector<size_t> rejected;  ///< feature indices rejected by the χ² gate
	std::vector<double> nis;       ///< NIS of each accepted observation
	std::vector<double> rejected_nis;  ///< NIS of each rejected observation
};

class ActiveSlamFilter : public mrpt::bayes::CKalmanFilterCapable<3, 3, 3, 2>
{
 public:
	ActiveSlamFilter(const SlamOptions& options, const base::LabmateModel& model);

	const SlamOptions& options() const { return options_; }

	/** Vehicle at @p x_v known exactly, empty map (eq 5.31). */
	void reset(const Eigen::Vector3d& x_v = Eigen::Vector3d::Zero());

	/** @name Map management
	 * @{ */
	/** A known feature at p_FinW with zero covariance and cross-covariances (5.6.2). */
	size_t addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW);
	/** A known feature from a saved map (5.6.2): at p_FinW with covariance @p P_FF (m²), not
	 * correlated with the vehicle or the other features; never deleted by the 5.7 rule. Its
	 * patch was saved from the head centre @p p_viewinW (default: where the head is now), the
	 * viewpoint of the 5.2.1 visibility rules. */
	size_t addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
	                       const Eigen::Matrix3d& P_FF,
	                       const std::optional<Eigen::Vector3d>& p_viewinW = std::nullopt);
	/** A new feature from its first measurement h (eqs 5.46–5.48). Returns its index. */
	size_t initialiseFeature(const std::string& label, const Eigen::Vector3d& h);
	/** Removes feature @p i from x and P (eq 5.49); later indices shift down by one. */
	void deleteFeature(size_t i);
	/** Adds @p Q (m², rad²) to the vehicle's covariance: the robot doubts where it is (it lost
	 * track) and searches wider before it trusts a measurement again. */
	void inflateVehicleCovariance(const Eigen::Matrix3d& Q);
	/** Makes the current vehicle pose the new world frame (eqs 5.50–5.52). */
	void zeroWorldFrame();
	/** Records a measurement attempt of feature @p i for the deletion rule (5.7). */
	void recordAttempt(size_t i, bool success);
	/** True when more than half of the last attempt_window attempts of @p i failed (5.7). */
	bool shouldDelete(size_t i) const;
	/** @} */

	/** @name Filtering
	 * @{ */
	/** Prediction for one control step (eqs 5.32–5.34). */
	void predict(const base::WheelControl& u);
	/** Update with the given observations (each feature at most once), after χ² gating. */
	UpdateReport update(const std::vector<Observation>& observations);
	/** χ²₃ gate threshold from options().gate_probability. */
	double gateThreshold() const { return gate_; }
	/** @} */

	/** @name Read access (brings a postponed update up to date first)
	 * @{ */
	size_t numFeatures();
	Eigen::Vector3d vehicle();
	Eigen::Matrix3d vehicleCovariance();
	Eigen::Vector3d feature(size_t i);
	Eigen::Matrix3d featureCovariance(size_t i);
	Eigen::VectorXd stateVector();
	Eigen::MatrixXd covariance();
	const FeatureInfo& info(size_t i) const { return info_.at(i); }
	/** Predicted measurement h(x_v, y_i) and its innovation covariance S_i = H P Hᵀ + R (eq 5.36).
	 */
	Eigen::Vector3d predictedMeasurement(size_t i);
	Eigen::Matrix3d innovationCovariance(size_t i);
	/** The joint innovation covariance of measurements of the distinct features @p features:
	 * S_J = H_J P H_Jᵀ + R_J (3k × 3k), their predictions' cross-covariances included. */
	Eigen::MatrixXd jointInnovationCovariance(const std::vector<size_t>& features);
	/** The measurement noise R (eq 5.41). */
	Eigen::Matrix3d measurementNoise() const;
	/** Brings x and P up to date and stops postponed tracking (no-op otherwise). */
	void synchronise();
	/** Replaces the whole state (sizes must match the feature bookkeeping); for tests. */
	void setState(const Eigen::VectorXd& x, const Eigen::MatrixXd& P);
	/** @} */

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
	void OnNormalizeStateVector() override;
	void OnPostIteration() override;

 private:
	Eigen::Vector3d vehicleRaw() const;
	Eigen::Matrix3d processNoise(const Eigen::Vector3d& x_v) const;
	Eigen::Vector3d featureRaw(size_t i) const;
	/** ∂f/∂x_v at @p x_v (standard) or from the propagated estimates (FEJ). */
	Eigen::Matrix3d transitionJacobian(const Eigen::Vector3d& x_v) const;
	/** H of feature i at (x_v, y) (standard) or at (x_{k|k−1}, first estimate of y) (FEJ). */
	MeasurementJacobians observationJacobians(size_t i, const Eigen::Vector3d& x_v,
	                                          const Eigen::Vector3d& y) const;
	/** Records x_{k|k−1}, the vehicle estimate right after a prediction (FEJ's linearisation). */
	void notePrediction(const Eigen::Vector3d& x_v_predicted);
	void appendFeature(const Eigen::Vector3d& y, const Eigen::MatrixXd& P_new, FeatureInfo info);
	/** One observation linearised at the prior state: active block, H, innovation and NIS. */
	struct PriorLinearisation
	{
		size_t feature = 0;
		Eigen::Matrix<double, 6, 1> a0;  ///< (x_v, y_i) at the prior
		Eigen::Matrix<double, 3, 6> H;
		Eigen::Vector3d nu;
		double nis = 0;
	};
	PriorLinearisation linearisePrior(const Observation& z) const;
	/** The three scalar updates of one gated observation (eqs 5.42–5.45). */
	void applyScalarUpdates(const PriorLinearisation& l);
	/** Sequential scalar updates of all observations (FilterSequential.cpp). */
	void updateSequential(const std::vector<Observation>& z);
	bool postponedApplies(const std::vector<Observation>& z) const;
	UpdateReport updatePostponed(const Observation& z);
	void predictPostponed();

	SlamOptions options_;
	base::LabmateModel model_;
	double gate_ = 0;
	std::vector<FeatureInfo> info_;
	base::WheelControl u_;
	Eigen::Vector3d xv_prior_ = Eigen::Vector3d::Zero();  ///< x_{k|k−1} of the vehicle (FEJ)
	bool skip_prediction_ = false;
	std::vector<Observation> pending_;
	UpdateReport report_;
	PostponedTracker33 tracker_;
};

}  // namespace mrolr::slam
