#include <mrolr/recog/images/ProjectedRun.h>
#include <mrolr/util/SimdClones.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace mrolr::recog
{
namespace
{
using Lens = RunProjection::Lens;

/** cv::projectPoints of one point of the camera frame, in OpenCV's order of operations; without
 * the distortion's terms when @p kDistorted is false (all of them 0: then the same bits for a
 * point in view, where r2 < 2 is finite, since x · 1 + 0 + 0 is x up to the sign of a zero, which
 * u = x fx + cx does not keep). */
template <bool kDistorted>
inline void project(const Lens& L, double X, double Y, double Z, double& u, double& v)
{
	const double iz = 1. / (Z + static_cast<double>(Z == 0));  // 1 when Z is 0, as OpenCV's
	const double x = X * iz, y = Y * iz;
	if constexpr (!kDistorted)
	{
		u = x * L.fx + L.cx, v = y * L.fy + L.cy;
		return;
	}
	const double r2 = x * x + y * y, r4 = r2 * r2, r6 = r4 * r2;
	const double a1 = 2 * x * y, a2 = r2 + 2 * x * x, a3 = r2 + 2 * y * y;
	const double cdist = 1 + L.k1 * r2 + L.k2 * r4 + L.k3 * r6;
	const double xd = x * cdist + L.p1 * a1 + L.p2 * a2;
	const double yd = y * cdist + L.p1 * a3 + L.p2 * a1;
	u = xd * L.fx + L.cx, v = yd * L.fy + L.cy;
}

/** The run's arithmetic on arrays (structure of arrays), to be vectorised. */
template <bool kDistorted>
inline void projectBody(const std::array<double, 9>& R, const std::array<double, 3>& t,
                        const Lens& L, const double (*p)[ProjectedRun::kMax],
                        const double (*d)[ProjectedRun::kMax], size_t n, ProjectedRun& out)
{
	for (size_t k = 0; k < n; ++k)
	{
		// Isometry3d * p: the linear part's rows, summed in Eigen's order, then the translation
		const double X = R[0] * p[0][k] + R[3] * p[1][k] + R[6] * p[2][k] + t[0];
		const double Y = R[1] * p[0][k] + R[4] * p[1][k] + R[7] * p[2][k] + t[1];
		const double Z = R[2] * p[0][k] + R[5] * p[1][k] + R[8] * p[2][k] + t[2];
		const double QX = X + (R[0] * d[0][k] + R[3] * d[1][k] + R[6] * d[2][k]);
		const double QY = Y + (R[1] * d[0][k] + R[4] * d[1][k] + R[7] * d[2][k]);
		const double QZ = Z + (R[2] * d[0][k] + R[5] * d[1][k] + R[8] * d[2][k]);
		out.x[k] = X, out.y[k] = Y, out.z[k] = Z;
		out.in_view[k] = static_cast<std::int64_t>(inView(X, Y, Z) & inView(QX, QY, QZ));
		double u, v, qu, qv;
		project<kDistorted>(L, X, Y, Z, u, v);
		project<kDistorted>(L, QX, QY, QZ, qu, qv);
		out.u[k] = u, out.v[k] = v, out.tu[k] = qu - u, out.tv[k] = qv - v;
	}
}

// R, t and L by value: the stores to out cannot change them, so that the loops vectorise
MROLR_SIMD_CLONES void projectArrays(const std::array<double, 9> R, const std::array<double, 3> t,
                                     const Lens L, const double (*p)[ProjectedRun::kMax],
                                     const double (*d)[ProjectedRun::kMax], size_t n,
                                     ProjectedRun& out)
{
	projectBody<true>(R, t, L, p, d, n, out);
}

MROLR_SIMD_CLONES void projectPinholeArrays(const std::array<double, 9> R,
                                            const std::array<double, 3> t, const Lens L,
                                            const double (*p)[ProjectedRun::kMax],
                                            const double (*d)[ProjectedRun::kMax], size_t n,
                                            ProjectedRun& out)
{
	projectBody<false>(R, t, L, p, d, n, out);
}

SampleBlock blockOf(const EdgeSample* first, size_t n)
{
	if (n > ProjectedRun::kMax)
		throw std::invalid_argument("RunProjection: more than kMax samples");
	SampleBlock b;
	b.n = n;
	for (size_t k = 0; k < n; ++k)
		for (int i = 0; i < 3; ++i) b.p[i][k] = first[k].p_O[i], b.d[i][k] = first[k].t_O[i];
	return b;
}
}  // namespace

std::vector<SampleBlock> sampleBlocksOf(const std::vector<EdgeSample>& samples)
{
	std::vector<SampleBlock> out;
	for (size_t first = 0; first < samples.size(); first += ProjectedRun::kMax)
		out.push_back(
		    blockOf(samples.data() + first, std::min(ProjectedRun::kMax, samples.size() - first)));
	return out;
}

RunProjection::RunProjection(const Eigen::Isometry3d& T_OinC, const cv::Matx33d& K,
                             const cv::Vec<double, 5>& D)
    : lens_{K(0, 0), K(1, 1), K(0, 2), K(1, 2), D[0], D[1], D[2], D[3], D[4]},
      distorted_(D != cv::Vec<double, 5>::all(0))
{
	for (int i = 0; i < 3; ++i)
	{
		t_[i] = T_OinC.translation()[i];
		for (int j = 0; j < 3; ++j) R_[3 * j + i] = T_OinC.linear()(i, j);
	}
}

void RunProjection::project(const SampleBlock& block, ProjectedRun& out) const
{
	out.n = block.n;
	if (distorted_)
		projectArrays(R_, t_, lens_, block.p, block.d, block.n, out);
	else
		projectPinholeArrays(R_, t_, lens_, block.p, block.d, block.n, out);
}

void RunProjection::project(const EdgeSample* first, size_t n, ProjectedRun& out) const
{
	project(blockOf(first, n), out);
}

}  // namespace mrolr::recog
