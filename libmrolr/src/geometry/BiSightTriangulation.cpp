// 3D point from (uL, vL, uR, vR) and head angles (thesis 4.2.5, eqs 4.34–4.50) with covariance.
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/geometry/RayTriangulation.h>

#include <sstream>

namespace mrolr::geometry
{
namespace
{
// One camera's ray in C0: origin a (optic centre, eq 4.41) and direction b (eq 4.43).
struct Ray
{
	Eigen::Vector3d origin, direction;
	Eigen::Matrix<double, 3, 2> J_dir_wrt_pixel;
};

Ray rayInC0(const Eigen::Isometry3d& T_camInC0, const PinholeCamera& cam, double u, double v)
{
	return {T_camInC0.translation(), T_camInC0.linear() * cam.backProject({u, v}),
	        T_camInC0.linear() * cam.backProjectJacobian()};
}

void requireInFront(const RayMidpoint& r)
{
	if (r.lambda > 0 && r.mu > 0) return;
	std::ostringstream s;
	s << "the rays meet behind the " << (r.lambda > 0 ? "right" : "left")
	  << " camera (distances along the rays " << r.lambda << ", " << r.mu << " m)";
	throw TriangulationError(s.str());
}
}  // namespace

Eigen::Vector3d BiSightHead::triangulatePoint(const StereoPixels& px,
                                              const HeadAngles& angles) const
{
	const Ray L = rayInC0(T_LinC0(angles), camera_, px.uL, px.vL);
	const Ray R = rayInC0(T_RinC0(angles), camera_, px.uR, px.vR);
	const RayMidpoint mid =
	    midpointOfCommonPerpendicular(L.origin, L.direction, R.origin, R.direction);
	requireInFront(mid);
	return mid.point;
}

Triangulation BiSightHead::triangulate(const StereoPixels& px, const HeadAngles& angles,
                                       double sigma_px) const
{
	if (!(sigma_px >= 0)) throw GeometryError("sigma_px must be >= 0");
	const Ray L = rayInC0(T_LinC0(angles), camera_, px.uL, px.vL);
	const Ray R = rayInC0(T_RinC0(angles), camera_, px.uR, px.vR);
	const RayMidpoint mid =
	    midpointOfCommonPerpendicular(L.origin, L.direction, R.origin, R.direction);
	requireInFront(mid);
	const Eigen::Matrix<double, 3, 6> J_dir =
	    midpointJacobianWrtDirections(L.origin, L.direction, R.origin, R.direction, mid.point);
	// Chain rule to the pixels: ∂m/∂(uL, vL, uR, vR) (3×4), then Σ = σ² J Jᵀ.
	Eigen::Matrix<double, 3, 4> J;
	J << J_dir.leftCols<3>() * L.J_dir_wrt_pixel, J_dir.rightCols<3>() * R.J_dir_wrt_pixel;
	Triangulation t;
	t.p_GinC0 = mid.point;
	t.cov = sigma_px * sigma_px * J * J.transpose();
	t.J_wrt_pixels = J;
	t.gap_m = mid.gap;
	return t;
}

}  // namespace mrolr::geometry
