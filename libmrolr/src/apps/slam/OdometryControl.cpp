#include <mrolr/apps/OdometryControl.h>

#include <cmath>
#include <stdexcept>

namespace mrolr::apps
{
base::WheelControl controlFromOdometry(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                       double dt_s, double D1)
{
	if (!(dt_s > 0))
		throw std::invalid_argument("odometry increment over a non-positive time step");
	const double theta = std::remainder(to[2] - from[2], 2 * M_PI);
	// Eqs 5.4/5.6 in the frame of `from`: forward = s·sinθ/θ, left = s·(1 − cosθ)/θ.
	const double c = std::cos(from[2]), s = std::sin(from[2]);
	const double dz = to[0] - from[0], dx = to[1] - from[1];
	const double forward = c * dz + s * dx, left = -s * dz + c * dx;
	const bool small = std::abs(theta) < 1e-6;
	const double a = small ? 1 - theta * theta / 6 : std::sin(theta) / theta;
	const double b = small ? theta / 2 : (1 - std::cos(theta)) / theta;
	const double arc = (forward * a + left * b) / (a * a + b * b);  // least squares along (a, b)
	return {(arc + D1 * theta) / dt_s, (arc - D1 * theta) / dt_s, dt_s};
}

}  // namespace mrolr::apps
