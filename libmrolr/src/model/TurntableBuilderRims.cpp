#include <mrolr/model/ArcOfBins.h>
#include <mrolr/model/TurntableBuilderRims.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/util/OptionsBinder.h>

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <tuple>

namespace mrolr::model
{
namespace
{
constexpr double kStepMm = 2.0;
constexpr int kBins = 36;  // 10° bins of a circle's angle

struct PoolSample
{
	Eigen::Vector3d p, t;
	size_t view, feature;
	bool conic;
};

struct Circle
{
	Eigen::Vector3d c, n, u, v;  // centre, normal, in-plane basis (mm)
	double r = 0;

	double angleOf(const Eigen::Vector3d& p) const
	{
		const Eigen::Vector3d q = p - c;
		return std::atan2(q.dot(v), q.dot(u));
	}
};

Circle withBasis(const Eigen::Vector3d& c, const Eigen::Vector3d& n, double r)
{
	Circle k{c, n.normalized(), {}, {}, r};
	k.u = k.n.unitOrthogonal();
	k.v = k.n.cross(k.u);
	return k;
}

/** The circle through three points, if they are not (nearly) collinear. */
std::optional<Circle> circleThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c)
{
	const Eigen::Vector3d ab = b - a, ac = c - a, n = ab.cross(ac);
	if (n.norm() < 1e-3 * ab.norm() * ac.norm()) return std::nullopt;
	const Eigen::Vector3d centre =
	    a +
	    (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n.squaredNorm());
	return withBasis(centre, n, (a - centre).norm());
}

bool isInlier(const Circle& k, const PoolSample& s, const RimOptions& o)
{
	const Eigen::Vector3d q = s.p - k.c;
	const double h = q.dot(k.n);
	const Eigen::Vector3d radial = q - h * k.n;
	const double rho = radial.norm();
	if (rho < 1e-9 || std::hypot(h, rho - k.r) > o.tol_mm) return false;
	const Eigen::Vector3d tangent = k.n.cross(radial / rho);
	return std::abs(tangent.dot(s.t)) >= std::cos(o.max_tangent_deg * M_PI / 180);
}

std::vector<size_t> inliersOf(const Circle& k, const std::vector<PoolSample>& pool,
                              const RimOptions& o)
{
	std::vector<size_t> in;
	for (size_t i = 0; i < pool.size(); ++i)
		if (isInlier(k, pool[i], o)) in.push_back(i);
	return in;
}

/** Least-squares plane (SVD) and circle (algebraic fit in the plane) through the inliers. */
std::optional<Circle> refit(const std::vector<PoolSample>& pool, const std::vector<size_t>& in)
{
	if (in.size() < 5) return std::nullopt;
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (size_t i : in) mean += pool[i].p;
	mean /= static_cast<double>(in.size());
	Eigen::MatrixXd X(in.size(), 3);
	for (size_t r = 0; r < in.size(); ++r) X.row(static_cast<long>(r)) = pool[in[r]].p - mean;
	const Eigen::JacobiSVD<Eigen::MatrixXd> svd(X, Eigen::ComputeThinV);
	Circle k = withBasis(mean, svd.matrixV().col(2), 0);
	Eigen::MatrixXd A(in.size(), 3);
	Eigen::VectorXd rhs(in.size());
	for (size_t r = 0; r < in.size(); ++r)
	{
		const Eigen::Vector3d q = pool[in[r]].p - mean;
		const double x = q.dot(k.u), y = q.dot(k.v);
		A.row(static_cast<long>(r)) << x, y, 1;
		rhs(static_cast<long>(r)) = -(x * x + y * y);
	}
	const Eigen::Vector3d D = A.colPivHouseholderQr().solve(rhs);
	const double cx = -D(0) / 2, cy = -D(1) / 2, r2 = cx * cx + cy * cy - D(2);
	if (!(r2 > 0)) return std::nullopt;
	return withBasis(mean + cx * k.u + cy * k.v, k.n, std::sqrt(r2));
}

/** Which 10° bins of @p k the conic inliers occupy. */
std::array<bool, kBins> conicBins(const Circle& k, const std::vector<PoolSample>& pool,
                                  const std::vector<size_t>& in)
{
	std::array<bool, kBins> bins{};
	for (size_t i : in)
		if (pool[i].conic)
		{
			const double a = k.angleOf(pool[i].p) + M_PI;
			bins[std::min(kBins - 1, static_cast<int>(a / (2 * M_PI) * kBins))] = true;
		}
	return bins;
}

size_t viewCount(const std::vector<PoolSample>& pool, const std::vector<size_t>& in)
{
	std::set<size_t> views;
	for (size_t i : in) views.insert(pool[i].view);
	return views.size();
}

bool acceptable(const Circle& k, const std::vector<PoolSample>& pool, const std::vector<size_t>& in,
                const RimOptions& o)
{
	if (k.r < o.min_radius_mm || k.r > o.max_radius_mm) return false;
	if (static_cast<int>(viewCount(pool, in)) < o.min_views) return false;
	const auto bins = conicBins(k, pool, in);
	return std::count(bins.begin(), bins.end(), true) * 360.0 / kBins >= o.min_arc_deg;
}

std::vector<PoolSample> poolOf(const std::vector<WireFrame>& views)
{
	std::vector<PoolSample> pool;
	for (size_t v = 0; v < views.size(); ++v)
		for (const auto& s : sampleWireFrame(views[v], kStepMm))
		{
			const auto f = static_cast<size_t>(s.feature);
			pool.push_back({s.p, s.tangent, v, f, f >= views[v].lines.size()});
		}
	return pool;
}

/** The hypothesis with most inliers among acceptable circles through three conic samples of
 * different features. */
std::optional<Circle> bestHypothesis(const std::vector<PoolSample>& pool, const RimOptions& o,
                                     std::mt19937& rng)
{
	std::vector<size_t> arcs;
	for (size_t i = 0; i < pool.size(); ++i)
		if (pool[i].conic) arcs.push_back(i);
	if (arcs.size() < 3) return std::nullopt;
	std::uniform_int_distribution<size_t> pick(0, arcs.size() - 1);
	std::optional<Circle> best;
	size_t best_n = 0;
	for (int it = 0; it < o.iterations; ++it)
	{
		const auto &a = pool[arcs[pick(rng)]], &b = pool[arcs[pick(rng)]],
		           &c = pool[arcs[pick(rng)]];
		const auto key = [](const PoolSample& s) { return std::pair(s.view, s.feature); };
		if (key(a) == key(b) && key(b) == key(c)) continue;
		const auto k = circleThrough(a.p, b.p, c.p);
		if (!k || k->r < o.min_radius_mm || k->r > o.max_radius_mm) continue;
		const auto in = inliersOf(*k, pool, o);
		if (in.size() > best_n && acceptable(*k, pool, in, o)) best_n = in.size(), best = k;
	}
	return best;
}

/** The arc of @p k covered by the inliers: the circle without its largest empty 10° gap. */
Conic3 arcOf(const Circle& k, const std::vector<PoolSample>& pool, const std::vector<size_t>& in)
{
	std::array<bool, kBins> bins{};
	for (size_t i : in)
		bins[std::min(kBins - 1,
		              static_cast<int>((k.angleOf(pool[i].p) + M_PI) / (2 * M_PI) * kBins))] = true;
	Conic3 c{0, k.c, k.n, k.u, k.r, k.r, 0, 2 * M_PI};
	std::tie(c.t1, c.t2) = arcOfBins(bins, -M_PI);
	return c;
}

/** Features with consume_fraction of their samples among @p in: (view, feature) pairs. */
std::set<std::pair<size_t, size_t>> consumed(const std::vector<PoolSample>& pool,
                                             const std::vector<size_t>& in, const RimOptions& o)
{
	std::map<std::pair<size_t, size_t>, std::pair<size_t, size_t>> count;  // on circle, total
	for (const auto& s : pool) ++count[{s.view, s.feature}].second;
	for (size_t i : in) ++count[{pool[i].view, pool[i].feature}].first;
	std::set<std::pair<size_t, size_t>> out;
	for (const auto& [key, n] : count)
		if (n.first >= o.consume_fraction * n.second) out.insert(key);
	return out;
}

void removeFeatures(std::vector<WireFrame>& views, const std::set<std::pair<size_t, size_t>>& gone)
{
	for (size_t v = 0; v < views.size(); ++v)
	{
		WireFrame& w = views[v];
		const size_t n_lines = w.lines.size();
		std::vector<Line3> lines;
		std::vector<Conic3> conics;
		for (size_t i = 0; i < n_lines; ++i)
			if (!gone.count({v, i})) lines.push_back(w.lines[i]);
		for (size_t i = 0; i < w.conics.size(); ++i)
			if (!gone.count({v, n_lines + i})) conics.push_back(w.conics[i]);
		w.lines = std::move(lines), w.conics = std::move(conics);
	}
}
}  // namespace

namespace
{
using R = RimOptions;
constexpr auto kOpt = util::Presence::Optional;  // [turntable]: every key of config/model.ini

const util::OptionsBinder<R>& rimOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<R>()
	        .flag("rim_fit", &R::enabled, kOpt)
	        .number("rim_tol_mm", &R::tol_mm, 0.01, 100, kOpt)
	        .number("rim_max_tangent_deg", &R::max_tangent_deg, 0, 90, kOpt)
	        .number("rim_min_arc_deg", &R::min_arc_deg, 10, 360, kOpt)
	        .integer("rim_min_views", &R::min_views, 1, 1000, kOpt)
	        .number("rim_min_radius_mm", &R::min_radius_mm, 0, 1e6, kOpt)
	        .number("rim_max_radius_mm", &R::max_radius_mm, 0, 1e6, kOpt)
	        .number("rim_consume_fraction", &R::consume_fraction, 0, 1, kOpt)
	        .integer("rim_iterations", &R::iterations, 1, 1000000, kOpt);
	return b;
}
}  // namespace

void RimOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s)
{
	rimOptionsBinder().load(cfg, s, *this);
}

void RimOptions::dump(std::ostream& out) const
{
	rimOptionsBinder().dump(out, *this);
}

std::vector<Conic3> fitRimsAcrossViews(std::vector<WireFrame>& views, const RimOptions& o)
{
	std::vector<Conic3> rims;
	if (!o.enabled) return rims;
	std::mt19937 rng(1);
	auto pool = poolOf(views);  // (view, feature) keys index the views as given
	std::set<std::pair<size_t, size_t>> all_gone;
	for (int round = 0; round < 32; ++round)
	{
		auto k = bestHypothesis(pool, o, rng);
		for (int r = 0; k && r < 3; ++r) k = refit(pool, inliersOf(*k, pool, o));
		if (!k) break;
		const auto in = inliersOf(*k, pool, o);
		if (!acceptable(*k, pool, in, o)) break;
		rims.push_back(arcOf(*k, pool, in));
		const auto gone = consumed(pool, in, o);
		all_gone.insert(gone.begin(), gone.end());
		const std::set<size_t> on_circle(in.begin(), in.end());
		std::vector<PoolSample> rest;
		for (size_t i = 0; i < pool.size(); ++i)
			if (!on_circle.count(i) && !gone.count({pool[i].view, pool[i].feature}))
				rest.push_back(pool[i]);
		pool = std::move(rest);
	}
	removeFeatures(views, all_gone);
	return rims;
}

}  // namespace mrolr::model
