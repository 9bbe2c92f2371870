#include "FullEkf.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace mrolr::slam::test
{
void FullEkf::predict(const Eigen::Vector3d& xv_new, const Eigen::Matrix3d& F_x,
                      const Eigen::Matrix3d& Q)
{
	const Eigen::Index n = x.size();
	Eigen::MatrixXd F = Eigen::MatrixXd::Identity(n, n);
	F.topLeftCorner<3, 3>() = F_x;
	Eigen::MatrixXd Qfull = Eigen::MatrixXd::Zero(n, n);
	Qfull.topLeftCorner<3, 3>() = Q;
	x.head<3>() = xv_new;
	P = (F * P * F.transpose() + Qfull).eval();
}

void FullEkf::update(int i, const Eigen::VectorXd& nu, const Eigen::MatrixXd& H_a,
                     const Eigen::MatrixXd& R)
{
	const Eigen::Index n = x.size(), M = nu.size();
	Eigen::MatrixXd H = Eigen::MatrixXd::Zero(M, n);
	H.leftCols(3) = H_a.leftCols(3);
	H.middleCols(3 + 3 * i, 3) = H_a.rightCols(3);
	const Eigen::MatrixXd S = H * P * H.transpose() + R;
	const Eigen::MatrixXd K = P * H.transpose() * S.inverse();
	x += K * nu;
	P = (P - K * S * K.transpose()).eval();
}

}  // namespace mrolr::slam::test
