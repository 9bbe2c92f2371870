// The body of revolution between coaxial rims, for the grasp checks.
#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/SolidSampling.h>

#include <algorithm>
#include <cmath>

namespace mrolr::arm
{
namespace
{
bool fullCircle(const model::Conic3& c)
{
	return std::abs(c.a - c.b) < 0.02 * std::max(c.a, c.b) && c.t2 - c.t1 > 2 * M_PI - 0.05;
}

/** True when @p b lies on @p a's axis (parallel normals, centre within tol of the axis line). */
bool coaxial(const model::Conic3& a, const model::Conic3& b, double tol_mm)
{
	const Eigen::Vector3d n = a.normal.normalized();
	if (std::abs(n.dot(b.normal.normalized())) < std::cos(2.5 * M_PI / 180)) return false;
	const Eigen::Vector3d d = b.centre - a.centre;
	return (d - d.dot(n) * n).norm() < tol_mm;
}

void sampleFrustum(const model::Conic3& lo, const model::Conic3& hi, const Eigen::Isometry3d& T,
                   double step_mm, std::vector<Eigen::Vector3d>& out)
{
	const Eigen::Vector3d n = lo.normal.normalized();
	const Eigen::Vector3d u = (lo.major - lo.major.dot(n) * n).normalized(), v = n.cross(u);
	const double length = (hi.centre - lo.centre).dot(n);
	const int rings = std::max(1, static_cast<int>(std::ceil(length / step_mm)));
	for (int i = 1; i < rings; ++i)  // the rims themselves are sampled as conics already
	{
		const double f = static_cast<double>(i) / rings;
		const Eigen::Vector3d c = lo.centre + f * (hi.centre - lo.centre);
		const double r = lo.a + f * (hi.a - lo.a);
		const int n_pts = std::max(8, static_cast<int>(std::ceil(2 * M_PI * r / step_mm)));
		for (int k = 0; k < n_pts; ++k)
		{
			const double t = 2 * M_PI * k / n_pts;
			out.push_back(T * Eigen::Vector3d(c + r * (std::cos(t) * u + std::sin(t) * v)));
		}
	}
}
}  // namespace

std::vector<Eigen::Vector3d> sampleRevolutionSurfaces(const model::WireFrame& wf,
                                                      const Eigen::Isometry3d& T, double step_mm,
                                                      double axis_tol_mm)
{
	std::vector<const model::Conic3*> circles;
	for (const auto& c : wf.conics)
		if (fullCircle(c)) circles.push_back(&c);
	std::vector<Eigen::Vector3d> out;
	std::vector<bool> used(circles.size(), false);
	for (size_t i = 0; i < circles.size(); ++i)
	{
		if (used[i]) continue;
		// the circles on this one's axis, in order along it
		const Eigen::Vector3d n = circles[i]->normal.normalized();
		std::vector<const model::Conic3*> axis;
		for (size_t j = i; j < circles.size(); ++j)
			if (!used[j] && coaxial(*circles[i], *circles[j], axis_tol_mm))
				axis.push_back(circles[j]), used[j] = true;
		std::sort(axis.begin(), axis.end(), [&](const model::Conic3* a, const model::Conic3* b)
		          { return a->centre.dot(n) < b->centre.dot(n); });
		for (size_t k = 1; k < axis.size(); ++k) sampleFrustum(*axis[k - 1], *axis[k], T, step_mm, out);
	}
	return out;
}

std::vector<Eigen::Vector3d> sampleSolid(const model::WireFrame& wf, const Eigen::Isometry3d& T,
                                         double step_mm)
{
	auto out = sampleWireFrame(wf, T, step_mm);
	const auto body = sampleRevolutionSurfaces(wf, T, step_mm);
	out.insert(out.end(), body.begin(), body.end());
	return out;
}

}  // namespace mrolr::arm
