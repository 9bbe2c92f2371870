#pragma once
// A plain full-state EKF written directly from the textbook equations (thesis eqs 5.32–5.34 and
// 5.57–5.62): the reference the postponed update must reproduce. Every step touches the whole x and
// P, with the full Jacobians.

#include <Eigen/Core>

namespace mrolr::slam::test
{
struct FullEkf
{
	Eigen::VectorXd x;  ///< (x_v, y_1 … y_N)
	Eigen::MatrixXd P;

	/** x_v ← xv_new, P ← ∇f P ∇fᵀ + blockdiag(Q, 0) with ∇f = blockdiag(F_x, I) (eq 5.33–5.34). */
	void predict(const Eigen::Vector3d& xv_new, const Eigen::Matrix3d& F_x,
	             const Eigen::Matrix3d& Q);

	/** Update with a measurement of feature @p i: innovation nu (M), H_a = (∂h/∂x_v, ∂h/∂y_i)
	 * (M×6), noise R (M×M): K = P Hᵀ S⁻¹, x += K ν, P −= K S Kᵀ with the full H (eqs 5.57–5.62). */
	void update(int i, const Eigen::VectorXd& nu, const Eigen::MatrixXd& H_a,
	            const Eigen::MatrixXd& R);

	Eigen::Vector3d vehicle() const { return x.head<3>(); }
	Eigen::Vector3d feature(int i) const { return x.segment<3>(3 + 3 * i); }
};

}  // namespace mrolr::slam::test
