#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/util/SimdClones.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mrolr::recog
{
namespace
{
constexpr int kSamplesPerFeature = 8;
}  // namespace

std::vector<Eigen::Vector3d> sphereDirections(int n)
{
	std::vector<Eigen::Vector3d> dirs;
	const double golden = M_PI * (3.0 - std::sqrt(5.0));
	for (int i = 0; i < n; ++i)
	{
		const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
		dirs.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
	}
	return dirs;
}

std::vector<Eigen::Vector3d> samplesOf(const Feature& f, int count)
{
	std::vector<Eigen::Vector3d> pts;
	if (f.isLine())
	{
		for (int i = 0; i < count; ++i) pts.push_back(f.p1 + (f.p2 - f.p1) * (i + 0.5) / count);
		return pts;
	}
	const Eigen::Vector3d a = f.u.unitOrthogonal(), b = f.u.cross(a);
	const double r = 0.5 * (f.a_mm + f.b_mm);
	for (int i = 0; i < count; ++i)
	{
		const double t = 2 * M_PI * i / count;
		pts.push_back(f.m + r * (std::cos(t) * a + std::sin(t) * b));
	}
	return pts;
}

SelfOcclusion::SelfOcclusion(const std::vector<Feature>& features_O, double margin_mm,
                             int directions)
    : normals_(sphereDirections(directions)),
      bodies_(revolutionBodiesOf(features_O)),
      margin_mm_(margin_mm)
{
	if (directions > static_cast<int>(View::kMaxFaces))
		throw std::invalid_argument("SelfOcclusion: " + std::to_string(directions) +
		                            " face directions, at most " + std::to_string(View::kMaxFaces));
	for (const auto& n : normals_) nx_.push_back(n.x()), ny_.push_back(n.y()), nz_.push_back(n.z());
	if (bodies_.size() > 64)
		throw std::invalid_argument("SelfOcclusion: " + std::to_string(bodies_.size()) +
		                            " bodies of revolution, at most 64");
	for (const auto& f : features_O) samples_.push_back(samplesOf(f, kSamplesPerFeature));
	offsets_ = offsetsOf(samples_, margin_mm);
	std::vector<Eigen::Vector3d> all;
	for (const auto& fs : samples_) all.insert(all.end(), fs.begin(), fs.end());
	balls_ = innerBalls(normals_, offsets_, all);
	for (const auto& fs : samples_)
	{
		samples_outside_.emplace_back();
		for (const auto& p : fs) samples_outside_.back().push_back(outsideFaces(offsets_, p));
	}
	if (bodies_.empty()) return;
	// the features off the bodies' surfaces (a cup's handle): they can hide a limb
	std::vector<std::vector<Eigen::Vector3d>> rest;
	for (const auto& fs : samples_)
	{
		const auto on = [&](const Eigen::Vector3d& p)
		{
			return std::any_of(bodies_.begin(), bodies_.end(),
			                   [&](const RevolutionBody& b) { return onSurface(b, p, margin_mm); });
		};
		if (!std::all_of(fs.begin(), fs.end(), on)) rest.push_back(fs);
	}
	if (!rest.empty()) rest_offsets_ = offsetsOf(rest, margin_mm);
}

std::vector<double> SelfOcclusion::offsetsOf(const std::vector<std::vector<Eigen::Vector3d>>& pts,
                                             double margin_mm) const
{
	std::vector<double> out;
	for (const auto& n : normals_)
	{
		double d = -std::numeric_limits<double>::infinity();
		for (const auto& fs : pts)
			for (const auto& p : fs) d = std::max(d, n.dot(p));
		out.push_back(d - margin_mm);
	}
	return out;
}

void SelfOcclusion::facesFrom(const std::vector<double>& offsets, const View::PerFace& nc,
                              View::Faces& f) const
{
	f.outside = {0, 0}, f.n = 0;
	for (size_t i = 0; i < offsets.size(); ++i)
	{
		if (nc[i] <= offsets[i]) continue;
		f.outside[i >> 6] |= std::uint64_t{1} << (i & 63);
		f.nx[f.n] = nx_[i], f.ny[f.n] = ny_[i], f.nz[f.n] = nz_[i];
		f.nc[f.n] = nc[i], f.gap[f.n] = nc[i] - offsets[i], f.offset[f.n] = offsets[i];
		++f.n;
	}
}

SelfOcclusion::View SelfOcclusion::viewFrom(const Eigen::Vector3d& c_O) const
{
	View v;
	v.c_O_ = c_O;
	// n·c over the face directions' arrays, in Vector3d::dot's order: (x + y) + z
	const double cx = c_O.x(), cy = c_O.y(), cz = c_O.z();
	for (size_t i = 0; i < nx_.size(); ++i) v.nc_[i] = nx_[i] * cx + ny_[i] * cy + nz_[i] * cz;
	facesFrom(offsets_, v.nc_, v.all_);
	v.balls_ = ballsSeenFrom(balls_, c_O);
	if (!rest_offsets_.empty()) facesFrom(rest_offsets_, v.nc_, v.rest_);
	v.bodies_.reserve(bodies_.size());
	for (const auto& b : bodies_) v.bodies_.push_back(bodySight(b, c_O));
	return v;
}

bool SelfOcclusion::hidden(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	return hidden(viewFrom(c_O), p_O);
}

bool SelfOcclusion::hidden(const View& v, const Eigen::Vector3d& p_O) const
{
	return crossesPolytope(v, p_O, outsideFaces(offsets_, p_O));
}

SelfOcclusion::PointSight SelfOcclusion::pointSight(const Eigen::Vector3d& p_O) const
{
	PointSight ps;
	ps.outside_all = outsideFaces(offsets_, p_O);
	if (!rest_offsets_.empty()) ps.outside_rest = outsideFaces(rest_offsets_, p_O);
	for (size_t k = 0; k < bodies_.size(); ++k)
		if (onSurface(bodies_[k], p_O, margin_mm_)) ps.on_bodies |= std::uint64_t{1} << k;
	ps.own = ownBall(normals_, offsets_, balls_, p_O);
	return ps;
}

std::array<std::uint64_t, 2> SelfOcclusion::outsideFaces(const std::vector<double>& offsets,
                                                         const Eigen::Vector3d& p_O) const
{
	std::array<std::uint64_t, 2> out = {0, 0};
	for (size_t i = 0; i < offsets.size(); ++i)
		if (nx_[i] * p_O.x() + ny_[i] * p_O.y() + nz_[i] * p_O.z() > offsets[i])
			out[i >> 6] |= std::uint64_t{1} << (i & 63);
	return out;
}

bool SelfOcclusion::contains(const Eigen::Vector3d& p_O) const
{
	for (size_t i = 0; i < normals_.size(); ++i)
		if (normals_[i].dot(p_O) > offsets_[i]) return false;
	return !normals_.empty();
}

bool SelfOcclusion::hiddenLimb(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	return hiddenLimb(viewFrom(c_O), p_O);
}

bool SelfOcclusion::hiddenLimb(const View& v, const Eigen::Vector3d& p_O) const
{
	// crossesPolytope's clipping over every face at once (a limb point has no PointSight: it
	// moves with the camera): the same arithmetic, so the same answers
	if (rest_offsets_.empty()) return false;
	// first, one face at a time, a face both ends are outside of (the camera is outside those of
	// rest_): a miss. Nine limb points in ten find one, most of them early.
	const View::Faces& f = v.rest_;
	for (size_t k = 0; k < f.n; ++k)
		if (f.nx[k] * p_O.x() + f.ny[k] * p_O.y() + f.nz[k] * p_O.z() > f.offset[k]) return false;
	using Faces = Eigen::Map<const Eigen::ArrayXd>;
	using Row = Eigen::Array<double, Eigen::Dynamic, 1, 0, View::kMaxFaces, 1>;  // no heap
	const auto n = static_cast<Eigen::Index>(rest_offsets_.size());
	const Faces nx(nx_.data(), n), ny(ny_.data(), n), nz(nz_.data(), n);
	const Faces d(rest_offsets_.data(), n), nc(v.nc_.data(), n);
	const Row np = nx * p_O.x() + ny * p_O.y() + nz * p_O.z();
	const double t1 = std::min(1.0, (np > d).select((d - nc) / (np - nc), 1.0).minCoeff());
	if (t1 <= 0) return false;
	return !((nc > d) && (nc - d >= t1 * (nc - np))).any();
}

// No early exit, so that the loop is vectorised (a hidden point tries every face anyway), and
// cloned for AVX2 (MROLR_SIMD_CLONES: the same answers).
MROLR_SIMD_CLONES bool SelfOcclusion::enteredLate(const View::Faces& f, double t1,
                                                  const Eigen::Vector3d& p_O)
{
	const double px = p_O.x(), py = p_O.y(), pz = p_O.z();
	const double *gap = f.gap.data(), *nc = f.nc.data();
	const double *nx = f.nx.data(), *ny = f.ny.data(), *nz = f.nz.data();
	long late = 0;
	for (size_t k = 0; k < f.n; ++k)
		late += gap[k] - t1 * (nc[k] - (nx[k] * px + ny[k] * py + nz[k] * pz)) >= 0 ? 1 : 0;
	return late != 0;
}

bool SelfOcclusion::crossesPolytope(const View& v, const Eigen::Vector3d& p_O,
                                    const std::array<std::uint64_t, 2>& p_outside,
                                    const OwnBall& own) const
{
	const View::Faces& f = v.all_;
	const View::PerFace& nc = v.nc_;
	const std::vector<double>& offsets = offsets_;
	// Cyrus–Beck clipping of x(t) = c + t (p − c), t in [0, 1], against n·x <= d, face by face
	// according to which end is outside it: a face both ends are outside of proves a miss, one
	// both are inside of bounds nothing, the segment leaves through those only p is outside of
	// (t1, the least of their t) and crosses when it has entered all those only c is outside of
	// by then.
	if ((p_outside[0] & f.outside[0]) | (p_outside[1] & f.outside[1])) return false;
	// a sight line through a ball inside the polytope crosses it: no clipping needed. The point's
	// own ball first: it proves most hidden points (OwnBall)
	if (own.r2 > 0 && throughOwnBall(own, v.c_O_, p_O)) return true;
	if (throughBall(v.balls_, p_O - v.c_O_)) return true;
	const auto np = [&](int i) { return nx_[i] * p_O.x() + ny_[i] * p_O.y() + nz_[i] * p_O.z(); };
	double t1 = 1;
	for (int w = 0; w < 2; ++w)
		for (std::uint64_t bits = p_outside[w]; bits; bits &= bits - 1)
		{
			const int i = 64 * w + __builtin_ctzll(bits);
			t1 = std::min(t1, (offsets[i] - nc[i]) / (np(i) - nc[i]));
		}
	if (t1 <= 0) return false;
	// it enters face k at (nc − d) / (nc − np) (np <= d < nc there): all of them before t1?
	return !enteredLate(f, t1, p_O);
}

bool SelfOcclusion::hiddenOnBodies(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	return hiddenOnBodies(viewFrom(c_O), p_O);
}

bool SelfOcclusion::hiddenOnBodies(const View& v, const Eigen::Vector3d& p_O) const
{
	return hiddenOnBodies(v, pointSight(p_O), p_O);
}

bool SelfOcclusion::crossesBodies(const View& v, const PointSight& ps,
                                  const Eigen::Vector3d& p_O) const
{
	for (size_t k = 0; k < bodies_.size(); ++k)
		if (((ps.on_bodies >> k) & 1u) && crossesSolid(bodies_[k], v.bodies_[k], p_O, margin_mm_))
			return true;
	return false;
}

std::vector<double> SelfOcclusion::visibleFractions(const Eigen::Vector3d& c_O) const
{
	const View v = viewFrom(c_O);
	std::vector<double> out;
	for (size_t k = 0; k < samples_.size(); ++k)
	{
		const auto& fs = samples_[k];
		int seen = 0;
		for (size_t j = 0; j < fs.size(); ++j)
			seen += crossesPolytope(v, fs[j], samples_outside_[k][j]) ? 0 : 1;
		out.push_back(fs.empty() ? 1.0 : static_cast<double>(seen) / fs.size());
	}
	return out;
}

}  // namespace mrolr::recog
