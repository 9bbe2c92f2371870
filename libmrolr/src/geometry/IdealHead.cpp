#include <mrolr/geometry/IdealHead.h>

#include <cmath>
#include <stdexcept>

namespace mrolr::geometry
{
Eigen::Vector3d idealHeadMeasure(const Eigen::Vector3d& m, double I)
{
	const double r = m.norm();
	if (!(r > 0)) throw std::invalid_argument("idealHeadMeasure: point at the head centre");
	const double p = std::hypot(m.x(), m.z());
	return {std::atan2(m.x(), m.z()), std::atan2(m.y(), p), std::atan(I / (2 * r))};
}

Eigen::Matrix3d idealHeadJacobian(const Eigen::Vector3d& m, double I)
{
	const double p2 = m.x() * m.x() + m.z() * m.z();
	const double p = std::sqrt(p2);
	const double r2 = p2 + m.y() * m.y();
	const double r = std::sqrt(r2);
	if (!(p > 0)) throw std::invalid_argument("idealHeadJacobian: point on the pan axis");
	Eigen::Matrix3d J;
	// pan: α = atan2(x, z)
	J.row(0) << m.z() / p2, 0.0, -m.x() / p2;
	// elevation: e = atan2(y, p)
	J.row(1) << -m.y() * m.x() / (p * r2), p / r2, -m.y() * m.z() / (p * r2);
	// vergence: γ = atan(I / 2r), dγ/dr = -(I/2) / (r² + I²/4), dr/dm = m / r
	const double dg_dr = -(I / 2) / (r2 + I * I / 4);
	J.row(2) = (dg_dr / r) * m.transpose();
	return J;
}

Eigen::Vector3d idealHeadInverse(const Eigen::Vector3d& h, double I)
{
	if (!(h.z() > 0 && h.z() < M_PI / 2))
		throw std::invalid_argument("idealHeadInverse: vergence must be in (0, pi/2)");
	const double r = I / (2 * std::tan(h.z()));
	const double ce = std::cos(h.y());
	return r * Eigen::Vector3d(ce * std::sin(h.x()), std::sin(h.y()), ce * std::cos(h.x()));
}

Eigen::Matrix3d idealHeadInverseJacobian(const Eigen::Vector3d& h, double I)
{
	if (!(h.z() > 0 && h.z() < M_PI / 2))
		throw std::invalid_argument("idealHeadInverseJacobian: vergence must be in (0, pi/2)");
	const double t = std::tan(h.z());
	const double r = I / (2 * t);
	const double dr_dg = -I / (2 * t * t) * (1 + t * t);
	const double sa = std::sin(h.x()), ca = std::cos(h.x());
	const double se = std::sin(h.y()), ce = std::cos(h.y());
	const Eigen::Vector3d dir(ce * sa, se, ce * ca);
	Eigen::Matrix3d J;
	J.col(0) = r * Eigen::Vector3d(ce * ca, 0, -ce * sa);
	J.col(1) = r * Eigen::Vector3d(-se * sa, ce, -se * ca);
	J.col(2) = dr_dg * dir;
	return J;
}

}  // namespace mrolr::geometry
