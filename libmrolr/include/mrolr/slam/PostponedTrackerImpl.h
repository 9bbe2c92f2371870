#pragma once
// Definitions of PostponedTracker (included by PostponedTracker.h only).

#include <Eigen/Cholesky>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mrolr::slam
{
namespace detail
{
/** P ← P − L Wᵀ for symmetric P and a symmetric L Wᵀ, in one pass over blocks of the lower
 * triangle, each written to both halves so that P stays exactly symmetric. */
template <class DP, class DL, class DW>
void subtractSymmetricProduct(Eigen::MatrixBase<DP>& P, const Eigen::MatrixBase<DL>& L,
                              const Eigen::MatrixBase<DW>& W)
{
	constexpr Eigen::Index b = 128;  // block edge: a block of each operand stays in cache
	const Eigen::Index n = P.rows();
	Eigen::MatrixXd B(b, b);
	for (Eigen::Index j = 0; j < n; j += b)
	{
		const Eigen::Index bj = std::min(b, n - j);
		for (Eigen::Index i = j; i < n; i += b)
		{
			const Eigen::Index bi = std::min(b, n - i);
			B.resize(bi, bj);
			B.noalias() =
			    P.block(i, j, bi, bj) - L.middleRows(i, bi) * W.middleRows(j, bj).transpose();
			if (i == j)
				for (Eigen::Index c = 0; c < bj; ++c)
					for (Eigen::Index r = c + 1; r < bi; ++r) B(c, r) = B(r, c);
			P.block(i, j, bi, bj) = B;
			if (i != j) P.block(j, i, bj, bi) = B.transpose();
		}
	}
}

}  // namespace detail

template <int V, int F>
template <class DX, class DP>
void PostponedTracker<V, F>::start(const Eigen::MatrixBase<DX>& x, const Eigen::MatrixBase<DP>& P,
                                   std::size_t feature)
{
	const Eigen::Index n = x.size();
	if (P.rows() != n || P.cols() != n)
		throw std::invalid_argument("PostponedTracker::start: x has " + std::to_string(n) +
		                            " entries but P is " + std::to_string(P.rows()) + "x" +
		                            std::to_string(P.cols()));
	if (n < V || (n - V) % F != 0)
		throw std::invalid_argument("PostponedTracker::start: state size " + std::to_string(n) +
		                            " is not vehicle + whole features");
	const auto N = static_cast<std::size_t>((n - V) / F);
	if (feature >= N)
		throw std::out_of_range("PostponedTracker::start: feature " + std::to_string(feature) +
		                        " of " + std::to_string(N));
	tracking_ = true;
	feature_ = feature;
	n_ = n;
	const std::vector<Eigen::Index> idx = activeIndices();
	x_a_ = x(idx, Eigen::all);
	P_aa_ = P(idx, idx);
	resetAccumulators();
}

template <int V, int F>
std::size_t PostponedTracker<V, F>::trackedFeature() const
{
	requireTracking("trackedFeature");
	return feature_;
}

template <int V, int F>
void PostponedTracker<V, F>::predict(const VecV& xv_new, const MatVV& F_x, const MatVV& Q)
{
	requireTracking("predict");
	x_a_.template head<V>() = xv_new;
	// F_a = blockdiag(F_x, I): only the vehicle rows change (eqs 5.116–5.120).
	Phi_.template topRows<V>() = (F_x * Phi_.template topRows<V>()).eval();
	P_aa_.template topRows<V>() = (F_x * P_aa_.template topRows<V>()).eval();
	P_aa_.template leftCols<V>() = (P_aa_.template leftCols<V>() * F_x.transpose()).eval();
	P_aa_.template topLeftCorner<V, V>() += Q;
	++pending_;
}

template <int V, int F>
template <int M>
void PostponedTracker<V, F>::update(const Eigen::Matrix<double, M, 1>& nu, const MatMA<M>& H_a,
                                    const Eigen::Matrix<double, M, M>& R)
{
	requireTracking("update");
	using MatMM = Eigen::Matrix<double, M, M>;
	const Eigen::Matrix<double, A, M> PHt = P_aa_ * H_a.transpose();
	const MatMM S = H_a * PHt + R;
	const Eigen::LLT<MatMM> llt(S);
	if (llt.info() != Eigen::Success)
		throw std::runtime_error(
		    "PostponedTracker::update: innovation covariance S not positive definite");
	// Accumulators first, with the old Φ_T (ordering notes after eq 5.142).
	const MatMA<M> B = H_a * Phi_;
	const MatMA<M> SinvB = llt.solve(B);
	Psi_ += B.transpose() * SinvB;
	Psi_ = (0.5 * (Psi_ + Psi_.transpose())).eval();
	mu_ += SinvB.transpose() * nu;
	// Gain of the active block, K_a = P_aa H_aᵀ S⁻¹ (eq 5.60).
	const Eigen::Matrix<double, A, M> K = llt.solve(PHt.transpose()).transpose();
	const MatAA I_KH = MatAA::Identity() - K * H_a;
	Phi_ = (I_KH * Phi_).eval();
	x_a_ += K * nu;
	// Joseph form keeps P_aa symmetric positive semi-definite.
	P_aa_ = (I_KH * P_aa_ * I_KH.transpose() + K * R * K.transpose()).eval();
	P_aa_ = (0.5 * (P_aa_ + P_aa_.transpose())).eval();
	++pending_;
}

template <int V, int F>
void PostponedTracker<V, F>::updateScalar(double nu, const MatMA<1>& h_a, double r)
{
	update<1>(Eigen::Matrix<double, 1, 1>(nu), h_a, Eigen::Matrix<double, 1, 1>(r));
}

template <int V, int F>
template <class DX, class DP>
void PostponedTracker<V, F>::catchUp(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P)
{
	requireTracking("catchUp");
	if (x.size() != n_ || P.rows() != n_ || P.cols() != n_)
		throw std::invalid_argument(
		    "PostponedTracker::catchUp: the state changed size since start() (" +
		    std::to_string(n_) + " -> " + std::to_string(x.size()) + ")");
	if (pending_ == 0) return;
	const std::vector<Eigen::Index> idx = activeIndices();
	// W = P(:, a) at time 0; its rows u are P_ua(0).
	const Eigen::Matrix<double, Eigen::Dynamic, A> W = P(Eigen::all, idx);
	x += W * mu_;  // eqs 5.109, 5.143
	// P_uu ← P_uu(0) − P_ua(0) Ψ_T P_au(0) (eqs 5.102, 5.144); the active rows are rewritten below.
	detail::subtractSymmetricProduct(P, (W * Psi_).eval(), W);
	// P_au ← Φ_T P_au(0) (eqs 5.86, 5.145–5.146); the active rows themselves come from P_aa.
	const Eigen::Matrix<double, A, Eigen::Dynamic> rowsA = Phi_ * W.transpose();
	P(idx, Eigen::all) = rowsA;
	P(Eigen::all, idx) = rowsA.transpose();
	P(idx, idx) = P_aa_;
	x(idx, Eigen::all) = x_a_;
	resetAccumulators();
}

template <int V, int F>
template <class DX, class DP>
void PostponedTracker<V, F>::stop(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P)
{
	catchUp(x, P);
	tracking_ = false;
}

template <int V, int F>
template <class DX, class DP>
void PostponedTracker<V, F>::switchTo(Eigen::MatrixBase<DX>& x, Eigen::MatrixBase<DP>& P,
                                      std::size_t feature)
{
	if (tracking_) catchUp(x, P);
	start(x, P, feature);
}

template <int V, int F>
void PostponedTracker<V, F>::requireTracking(const char* what) const
{
	if (!tracking_)
		throw std::logic_error(std::string("PostponedTracker::") + what +
		                       ": no feature is being tracked (call start)");
}

template <int V, int F>
void PostponedTracker<V, F>::resetAccumulators()
{
	Phi_.setIdentity();
	Psi_.setZero();
	mu_.setZero();
	pending_ = 0;
}

template <int V, int F>
std::vector<Eigen::Index> PostponedTracker<V, F>::activeIndices() const
{
	std::vector<Eigen::Index> idx(A);
	for (int k = 0; k < V; ++k) idx[k] = k;
	const auto first = static_cast<Eigen::Index>(V + F * feature_);
	for (int k = 0; k < F; ++k) idx[V + k] = first + k;
	return idx;
}

extern template class PostponedTracker<3, 3>;

}  // namespace mrolr::slam
