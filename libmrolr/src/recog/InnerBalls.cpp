#include <mrolr/recog/InnerBalls.h>
#include <mrolr/util/SimdClones.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mrolr::recog
{
namespace
{
constexpr int kGrid = 9;             // candidate centres per axis of the points' box
constexpr double kMinRadius_mm = 1;  // smaller balls catch next to nothing
constexpr double kSpread = 0.7;      // a next centre lies beyond this fraction of a chosen radius
/** A point's own ball (ownBall) lies next to it, so that smaller ones still catch sight lines. */
constexpr double kMinOwnRadius_mm = 0.5;

struct Ball
{
	Eigen::Vector3d c;
	double r;
};

/** min over i of offsets[i] − n_i·c (n_i·c in Vector3d::dot's order), four faces at a time (GCC's
 * vector extension: AVX in the AVX2 clone): the balls' searches ask it of hundreds of centres. */
MROLR_SIMD_CLONES double leastSlack(const double* nx, const double* ny, const double* nz,
                                    const double* offsets, size_t n, double cx, double cy,
                                    double cz)
{
	typedef double V4 __attribute__((vector_size(32)));
	V4 least = {HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL};
	const V4 x = {cx, cx, cx, cx}, y = {cy, cy, cy, cy}, z = {cz, cz, cz, cz};
	size_t i = 0;
	for (; i + 4 <= n; i += 4)
	{
		V4 a, b, c, d;
		std::memcpy(&a, nx + i, sizeof a), std::memcpy(&b, ny + i, sizeof b);
		std::memcpy(&c, nz + i, sizeof c), std::memcpy(&d, offsets + i, sizeof d);
		const V4 slack = d - (a * x + b * y + c * z);
		least = slack < least ? slack : least;
	}
	double r = std::min(std::min(least[0], least[1]), std::min(least[2], least[3]));
	for (; i < n; ++i) r = std::min(r, offsets[i] - (nx[i] * cx + ny[i] * cy + nz[i] * cz));
	return r;
}

/** The polytope's faces by coordinate, as leastSlack reads them. */
class Faces
{
 public:
	Faces(const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& offsets)
	    : offsets_(offsets)
	{
		for (const auto& n : normals)
			nx_.push_back(n.x()), ny_.push_back(n.y()), nz_.push_back(n.z());
	}
	/** The radius of the largest ball about @p c inside every face, less @p margin_mm. */
	double radiusAt(const Eigen::Vector3d& c, double margin_mm) const
	{
		return leastSlack(nx_.data(), ny_.data(), nz_.data(), offsets_.data(), nx_.size(), c.x(),
		                  c.y(), c.z()) -
		       margin_mm;
	}

 private:
	std::vector<double> nx_, ny_, nz_;
	const std::vector<double>& offsets_;
};
}  // namespace

InnerBalls innerBalls(const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& offsets,
                      const std::vector<Eigen::Vector3d>& points, double margin_mm)
{
	InnerBalls out;
	out.r2.fill(-1);
	if (points.empty() || normals.empty()) return out;
	Eigen::Vector3d lo = points.front(), hi = points.front();
	for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
	const Faces faces(normals, offsets);
	std::vector<Ball> candidates;
	for (int i = 0; i < kGrid; ++i)
		for (int j = 0; j < kGrid; ++j)
			for (int k = 0; k < kGrid; ++k)
			{
				const Eigen::Vector3d f = (Eigen::Vector3d(i, j, k).array() + 0.5) / kGrid;
				const Eigen::Vector3d c = lo + (hi - lo).cwiseProduct(f);
				const double r = faces.radiusAt(c, margin_mm);
				if (r >= kMinRadius_mm) candidates.push_back({c, r});
			}
	std::stable_sort(candidates.begin(), candidates.end(),
	                 [](const Ball& a, const Ball& b) { return a.r > b.r; });
	std::vector<Ball> chosen;
	for (const auto& b : candidates)
	{
		if (chosen.size() == InnerBalls::kMax) break;
		const bool apart =
		    std::all_of(chosen.begin(), chosen.end(),
		                [&](const Ball& c) { return (c.c - b.c).norm() >= kSpread * c.r; });
		if (apart) chosen.push_back(b);
	}
	for (const auto& b : chosen)
	{
		out.x[out.n] = b.c.x(), out.y[out.n] = b.c.y(), out.z[out.n] = b.c.z();
		out.r2[out.n] = b.r * b.r;
		++out.n;
	}
	return out;
}

OwnBall ownBall(const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& offsets,
                const InnerBalls& balls, const Eigen::Vector3d& p_O, double margin_mm)
{
	OwnBall out;
	const Faces faces(normals, offsets);
	double widest = 0;  // radius over distance from p_O
	const auto consider = [&](const Eigen::Vector3d& c)
	{
		const double q = (c - p_O).norm();
		if (!(q > 0)) return;
		const double r = faces.radiusAt(c, margin_mm);
		if (r < kMinOwnRadius_mm || r / q <= widest) return;
		widest = r / q;
		out = {c.x(), c.y(), c.z(), r * r};
	};
	if (balls.n > 0)
	{
		const Eigen::Vector3d g(balls.x[0], balls.y[0], balls.z[0]);
		for (int k = 1; k <= 16; ++k) consider(p_O + (g - p_O) * (k / 16.0));
	}
	Eigen::Vector3d outward = Eigen::Vector3d::Zero();
	for (size_t i = 0; i < normals.size(); ++i)
		if (offsets[i] - normals[i].dot(p_O) < 1) outward += normals[i];
	if (outward.norm() > 0)
		for (double s_mm = 0.5; s_mm <= 128; s_mm *= M_SQRT2)
			consider(p_O - outward.normalized() * s_mm);
	return out;
}

BallsSeen ballsSeenFrom(const InnerBalls& balls, const Eigen::Vector3d& c_O)
{
	BallsSeen s;
	for (size_t b = 0; b < InnerBalls::kMax; ++b)
	{
		const double ox = balls.x[b] - c_O.x(), oy = balls.y[b] - c_O.y(),
		             oz = balls.z[b] - c_O.z();
		s.ox[b] = ox, s.oy[b] = oy, s.oz[b] = oz, s.r2[b] = balls.r2[b];
		s.oo[b] = ox * ox + oy * oy + oz * oz;
		s.camera_inside = s.camera_inside || s.oo[b] <= s.r2[b];
	}
	return s;
}

// every ball at once, no early exit and no branch, so that the loop is vectorised
// (MROLR_SIMD_CLONES)
MROLR_SIMD_CLONES bool throughBall(const BallsSeen& seen, const Eigen::Vector3d& d_O)
{
	const double dx = d_O.x(), dy = d_O.y(), dz = d_O.z();
	const double dd = dx * dx + dy * dy + dz * dz;
	long hit = 0;
	for (size_t b = 0; b < InnerBalls::kMax; ++b)
	{
		const double od = seen.ox[b] * dx + seen.oy[b] * dy + seen.oz[b] * dz;
		hit += static_cast<long>(segmentMeetsBall(od, seen.oo[b], dd, seen.r2[b]));
	}
	return seen.camera_inside || hit != 0;
}

}  // namespace mrolr::recog
