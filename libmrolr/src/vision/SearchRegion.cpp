#include <mrolr/geometry/IdealHead.h>
#include <mrolr/vision/SearchRegion.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace mrolr::vision
{
using geometry::BiSightHead;
using geometry::HeadAngles;
using geometry::Side;

double ImageEllipse::mahalanobis2(const Eigen::Vector2d& uv) const
{
	const Eigen::Vector2d d = uv - centre;
	return d.dot(cov.ldlt().solve(d));
}

cv::Rect ImageEllipse::boundingBox() const
{
	const double hu = n_sigma * std::sqrt(std::max(cov(0, 0), 0.0));
	const double hv = n_sigma * std::sqrt(std::max(cov(1, 1), 0.0));
	const int u0 = static_cast<int>(std::floor(centre.x() - hu));
	const int v0 = static_cast<int>(std::floor(centre.y() - hv));
	const int u1 = static_cast<int>(std::ceil(centre.x() + hu));
	const int v1 = static_cast<int>(std::ceil(centre.y() + hv));
	return {u0, v0, u1 - u0 + 1, v1 - v0 + 1};
}

double ImageEllipse::area() const
{
	return M_PI * n_sigma * n_sigma * std::sqrt(std::max(cov.determinant(), 0.0));
}

ImageEllipse projectPointCovariance(const BiSightHead& head, Side side, const HeadAngles& angles,
                                    const Eigen::Vector3d& p_GinC0, const Eigen::Matrix3d& cov_C0,
                                    double n_sigma)
{
	Eigen::Matrix<double, 4, 3> J4;
	const geometry::StereoPixels px = head.project(p_GinC0, angles, &J4);
	const int row = side == Side::Left ? 0 : 2;
	const Eigen::Matrix<double, 2, 3> J = J4.middleRows<2>(row);
	ImageEllipse e;
	e.centre = side == Side::Left ? Eigen::Vector2d(px.uL, px.vL) : Eigen::Vector2d(px.uR, px.vR);
	e.cov = J * cov_C0 * J.transpose();
	e.cov = 0.5 * (e.cov + e.cov.transpose()).eval();
	e.n_sigma = n_sigma;
	return e;
}

ImageEllipse projectInnovation(const BiSightHead& head, Side side, const HeadAngles& angles,
                               const Eigen::Vector3d& h_pred, const Eigen::Matrix3d& S,
                               double n_sigma)
{
	const double I = head.options().interocular_m;
	const Eigen::Vector3d p = geometry::idealHeadInverse(h_pred, I);
	const Eigen::Matrix3d G = geometry::idealHeadInverseJacobian(h_pred, I);
	return projectPointCovariance(head, side, angles, p, G * S * G.transpose(), n_sigma);
}

double EpipolarBand::distance(const Eigen::Vector2d& uv) const
{
	const Eigen::Vector2d ab = b - a;
	const double len2 = ab.squaredNorm();
	const double t = len2 > 0 ? std::clamp((uv - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
	return (uv - (a + t * ab)).norm();
}

cv::Rect EpipolarBand::boundingBox() const
{
	// Clamped so that a ray grazing the right camera cannot overflow int; images are far smaller.
	auto c = [](double x) { return std::clamp(x, -1e6, 1e6); };
	const int u0 = static_cast<int>(std::floor(c(std::min(a.x(), b.x()) - band_px)));
	const int v0 = static_cast<int>(std::floor(c(std::min(a.y(), b.y()) - band_px)));
	const int u1 = static_cast<int>(std::ceil(c(std::max(a.x(), b.x()) + band_px)));
	const int v1 = static_cast<int>(std::ceil(c(std::max(a.y(), b.y()) + band_px)));
	return {u0, v0, u1 - u0 + 1, v1 - v0 + 1};
}

namespace
{
/** The right-camera z of the left-ray point at depth d (thesis axes, z along the optic axis). */
Eigen::Vector3d rayPointInC0(const BiSightHead& head, const HeadAngles& angles,
                             const Eigen::Vector2d& uvL, double depth)
{
	const Eigen::Vector3d ray_L = head.camera().backProject(uvL);  // z = 1
	return head.T_LinC0(angles) * (depth * ray_L);
}
}  // namespace

EpipolarBand epipolarBand(const BiSightHead& head, const HeadAngles& angles,
                          const Eigen::Vector2d& uvL, double min_depth_m, double max_depth_m,
                          double band_px)
{
	// Raise the near depth until the ray point is in front of the right camera (bisection on a
	// monotone function of depth along a straight ray).
	auto inFront = [&](double d) {
		return head.pointInCamera(Side::Right, rayPointInC0(head, angles, uvL, d), angles).z() >
		       1e-3;
	};
	double near = min_depth_m;
	if (!inFront(near))
	{
		if (!inFront(max_depth_m))
			throw geometry::ProjectionError(
			    "epipolarBand: the left ray is behind the right camera");
		double lo = near, hi = max_depth_m;
		for (int i = 0; i < 60; ++i) (inFront(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
		near = hi;
	}
	auto toRight = [&](double d)
	{
		const Eigen::Vector3d m =
		    head.pointInCamera(Side::Right, rayPointInC0(head, angles, uvL, d), angles);
		return head.camera().project(m);
	};
	return EpipolarBand{toRight(near), toRight(max_depth_m), band_px};
}

}  // namespace mrolr::vision
