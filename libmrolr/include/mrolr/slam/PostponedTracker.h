#pragma once
/** Davison's postponed ("continuous tracking") EKF update, thesis appendix C (eqs 5.53–5.146).
 *
 * The full EKF-SLAM state is x = (x_v, y_1 … y_N) with covariance P: a vehicle block of size V
 * (here (z, x, φ) in W) followed by N features of size F (3-D points in W). While one feature i is
 * tracked, a prediction moves only x_v (eq 5.53) and a measurement depends only on x_v and y_i
 * (eq 5.54). Then, with the "active" block a = (x_v, y_i) and the rest u = (y_j)_{j≠i},
 *
 *   P_au(t) = Φ_T · P_au(0)                 Φ_T = [E_T F_T; H_T G_T]          (eqs 5.86–5.101)
 *   P_uu(t) = P_uu(0) − P_ua(0) Ψ_T P_au(0)  Ψ_T = [A_T B_T; C_T D_T]          (eqs 5.102–5.108)
 *   x_u(t)  = x_u(0) + P_ua(0) μ_T           μ_T = (m_T; n_T)                  (eqs 5.109–5.113)
 *
 * so a tracking step only touches x_a, P_aa (6×6 here) and the accumulators: its cost does not
 * depend on N. The accumulators follow, for a prediction with F_a = blockdiag(F_x, I):
 *   Φ_T ← F_a Φ_T                                                   (eqs 5.119–5.120)
 * and for a measurement with Jacobian H_a = (∂h/∂x_v, ∂h/∂y_i), innovation ν and noise R, using the
 * old Φ_T (the ordering notes after eq 5.142), with B = H_a Φ_T and S = H_a P_aa H_aᵀ + R:
 *   Ψ_T ← Ψ_T + Bᵀ S⁻¹ B,   μ_T ← μ_T + Bᵀ S⁻¹ ν,   Φ_T ← (I − K_a H_a) Φ_T   (eqs 5.134–5.142)
 * One catch-up (eqs 5.143–5.146) then brings every y_j, P_xyj, P_yiyj and P_yjyk up to date in
 * O(N²) and restarts the accumulators. The result equals the full EKF update exactly (up to
 * rounding); Ψ_T is the stacked form of A_T … D_T and μ_T of m_T, n_T.
 *
 * Storage: the tracker keeps x_a, P_aa and the accumulators; the caller keeps the full x and P,
 * whose blocks other than the active ones stay at their values at start() (time 0) until
 * catchUp(). The caller must not modify x or P between start() and catchUp()/stop().
 *
 * @tparam V vehicle state size, @tparam F feature state size. */

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mrolr::slam
{
template <int V, int F>
class PostponedTracker
{
 public:
	static constexpr int A = V + F;  ///< size of the active block (x_v, y_i)
	using VecV = Eigen::Matrix<double, V, 1>;
	using VecF = Eigen::Matrix<double, F, 1>;
	using MatVV = Eigen::Matrix<double, V, V>;
	using VecA = Eigen::Matrix<double, A, 1>;
	using MatAA = Eigen::Matrix<double, A, A>;
	template <int M>
	using MatMA = Eigen::Matrix<double, M, A>;

	/** Starts tracking feature @p feature (0-based) of the full state (x, P): copies x_v, y_i and
	 * P_aa and resets the accumulators. Throws std::invalid_argument on inconsistent sizes and
	 * std::out_of_range for a feature index ≥ N. Any previous tracking is dropped (call catchUp
	 * first to keep it). */
	template <class DX, class DP>
	void start(const Eigen::MatrixBase<DX>& x, const Eigen::MatrixBase<DP>& P, std::size_t feature);

	/** True between start() and stop(). */
	bool tracking() const { return tracking_; }
	/** The tracked feature index; throws std::logic_error when not tracking. */
	std::size_t trackedFeature() const;
	/** Number of predictions and measurements since start() or the last catch-up. */
	std::size_t pendingSteps() const { return pending_; }

	/** Current (x_v, y_i) and its covariance P_aa; always up to date. */
	const VecA& activeState() const { return x_a_; }
	const MatAA& activeCovariance() const { return P_aa_; }
	VecV vehicle() const { return x_a_.template head<V>(); }
	VecF feature() const { return x_a_.template tail<F>(); }

	/** Prediction (eqs 5.114–5.120): x_v ← f_v(x_v, u) = @p xv_new, P_xx ← F_x P_xx F_xᵀ + Q,
	 * P_xyi ← F_x P_xyi; the features do not move. O(1) in N. */
	void predict(const VecV& xv_new, const MatVV& F_x, const MatVV& Q);

	/** Measurement of the tracked feature (eqs 5.121–5.142) with innovation @p nu (z − h, angles
	 * already wrapped by the caller), Jacobian @p H_a = (∂h/∂x_v, ∂h/∂y_i) and noise @p R (M×M).
	 * P_aa is updated in Joseph form. Throws std::runtime_error if S is not positive definite.
	 * O(1) in N. M = 1 is the sequential scalar update (eqs 5.42–5.45). */
	template <int M>
	void update(const Eigen::Matrix<double, M, 1>& nu, const MatMA<M>& H_a,
	            const Eigen::Matrix<double, M, M>& R);

	/** Sequential scalar update of one measurement component (eqs 5.42–5.45). */
	void updateScalar(double nu, const MatMA<1>& h_a, double r);

	/** Brings the full (x, P) up to date (eqs 5.143–5.146) and restarts the accumulators; tracking
	 * of the same feature continues. O(N²). @p x and @p P must be the ones given to start().
	 * Throws std::logic_error when not tracking, std::invalid_argument if the sizes changed. */
	template <class DX, class DP>
	void catchUp(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P);

	/** catchUp() and stop tracking. */
	template <class DX, class DP>
	void stop(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P);

	/** Switches tracking to @p feature: catchUp() (if tracking) then start(). */
	template <class DX, class DP>
	void switchTo(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P, std::size_t feature);

 private:
	void requireTracking(const char* what) const;
	void resetAccumulators();
	std::vector<Eigen::Index> activeIndices() const;

	bool tracking_ = false;
	std::size_t feature_ = 0;
	Eigen::Index n_ = 0;  ///< full state size at start()
	std::size_t pending_ = 0;
	VecA x_a_ = VecA::Zero();
	MatAA P_aa_ = MatAA::Zero();
	MatAA Phi_ = MatAA::Identity();  ///< Φ_T = [E_T F_T; H_T G_T]
	MatAA Psi_ = MatAA::Zero();      ///< Ψ_T = [A_T B_T; C_T D_T]
	VecA mu_ = VecA::Zero();         ///< μ_T = (m_T; n_T)
};

/** The tracker for MROLR's EKF: vehicle (z, x, φ) and 3-D point features. */
using PostponedTracker33 = PostponedTracker<3, 3>;

}  // namespace mrolr::slam

#include <mrolr/slam/PostponedTrackerImpl.h>
