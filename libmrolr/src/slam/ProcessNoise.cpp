// Second-order term of the process noise (Gaussian second-order filter, e.g. Bar-Shalom, Li &
// Kirubarajan 2001, 10.3): Q₂(a, b) = ½ tr(H_a U H_b U).
#include <mrolr/slam/ProcessNoise.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace mrolr::slam
{
namespace
{
using Hessians = std::array<Eigen::Matrix2d, 3>;

Eigen::Vector3d moveWith(const base::LabmateModel& m, const Eigen::Vector3d& x_v,
                         const base::WheelControl& u, const Eigen::Vector2d& dv)
{
	return m.move(x_v, {u.v1_mps + dv[0], u.v2_mps + dv[1], u.dt_s});
}

Hessians controlHessians(const base::LabmateModel& m, const Eigen::Vector3d& x_v,
                         const base::WheelControl& u)
{
	const double h = 1e-3 * std::max({std::abs(u.v1_mps), std::abs(u.v2_mps), 1e-3});
	const Eigen::Vector2d e[2] = {{h, 0}, {0, h}};
	Hessians H;
	for (int i = 0; i < 2; ++i)
		for (int j = 0; j < 2; ++j)
		{
			const Eigen::Vector3d d2 =
			    moveWith(m, x_v, u, e[i] + e[j]) - moveWith(m, x_v, u, e[i] - e[j]) -
			    moveWith(m, x_v, u, e[j] - e[i]) + moveWith(m, x_v, u, -e[i] - e[j]);
			for (int a = 0; a < 3; ++a) H[a](i, j) = d2[a] / (4 * h * h);
		}
	return H;
}
}  // namespace

Eigen::Matrix3d secondOrderProcessNoise(const base::LabmateModel& model, const Eigen::Vector3d& x_v,
                                        const base::WheelControl& u)
{
	const Eigen::Matrix2d U = model.controlCovariance(u);
	const Hessians H = controlHessians(model, x_v, u);
	Eigen::Matrix3d Q2;
	for (int a = 0; a < 3; ++a)
		for (int b = 0; b < 3; ++b) Q2(a, b) = 0.5 * (H[a] * U * H[b] * U).trace();
	return Q2;
}

}  // namespace mrolr::slam
