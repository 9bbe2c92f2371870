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
struct Lens
{
	double fx, fy, cx, cy, k1, k2, p1, p2, k3;
};

/** cv::projectPoints of one point of the camera frame, in OpenCV's order of operations. */
inline void project(const Lens& L, double X, double Y, double Z, double& u, double& v)
{
	const double iz = 1. / (Z + static_cast<double>(Z == 0));  // 1 when Z is 0, as OpenCV's
	const double x = X * iz, y = Y * iz;
	const double r2 = x * x + y * y, r4 = r2 * r2, r6 = r4 * r2;
	const double a1 = 2 * x * y, a2 = r2 + 2 * x * x, a3 = r2 + 2 * y * y;
	const double cdist = 1 + L.k1 * r2 + L.k2 * r4 + L.k3 * r6;
	const double xd = x * cdist + L.p1 * a1 + L.p2 * a2;
	const double yd = y * cdist + L.p1 * a3 + L.p2 * a1;
	u = xd * L.fx + L.cx, v = yd * L.fy + L.cy;
}

/** The run's arithmetic on arrays (structure of arrays), vectorised. */
MROLR_SIMD_CLONES void projectArrays(const std::array<double, 9> R, const std::array<double, 3> t,
                                     const Lens L, const double (*p)[ProjectedRun::kMax],
                                     const double (*d)[ProjectedRun::kMax], size_t n,
                                     ProjectedRun& out)
{
	// R, t and L by value: the stores to out cannot change them, so that the loop vectorises
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
		project(L, X, Y, Z, u, v);
		project(L, QX, QY, QZ, qu, qv);
		out.u[k] = u, out.v[k] = v, out.tu[k] = qu - u, out.tv[k] = qv - v;
	}
}

SampleBlock blockOf(const EdgeSample* first, size_t n)
{
	if (n > ProjectedRun::kMax) throw std::invalid_argument("projectRun: more than kMax samples");
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

void projectRun(const Eigen::Isometry3d& T_OinC, const cv::Matx33d& K, const cv::Vec<double, 5>& D,
                const SampleBlock& block, ProjectedRun& out)
{
	std::array<double, 9> R;  // column-major: R[3 j + i] = R(i, j)
	std::array<double, 3> t;
	for (int i = 0; i < 3; ++i)
	{
		t[i] = T_OinC.translation()[i];
		for (int j = 0; j < 3; ++j) R[3 * j + i] = T_OinC.linear()(i, j);
	}
	const Lens L{K(0, 0), K(1, 1), K(0, 2), K(1, 2), D[0], D[1], D[2], D[3], D[4]};
	out.n = block.n;
	projectArrays(R, t, L, block.p, block.d, block.n, out);
}

void projectRun(const Eigen::Isometry3d& T_OinC, const cv::Matx33d& K, const cv::Vec<double, 5>& D,
                const EdgeSample* first, size_t n, ProjectedRun& out)
{
	projectRun(T_OinC, K, D, blockOf(first, n), out);
}

}  // namespace mrolr::recog
