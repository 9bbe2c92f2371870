#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <unordered_map>

namespace mrolr::stereo
{
namespace
{
/** An edgel's crossing of its integer scanline. */
struct Sample
{
	int string = 0, edgel = 0, row = 0;
	double x = 0;
	cv::Point2d grad;
};

struct Candidate
{
	int left = 0, right = 0;  ///< sample indices
	double d = 0, support = 0;
};

std::vector<Sample> scanlineSamples(const std::vector<EdgeString>& strings, double min_sin)
{
	std::vector<Sample> out;
	for (size_t s = 0; s < strings.size(); ++s)
		for (size_t i = 0; i < strings[s].size(); ++i)
		{
			const Edgel& e = strings[s][i];
			const cv::Point2d t = e.tangent();
			if (std::abs(t.y) < min_sin) continue;
			const int row = static_cast<int>(std::lround(e.p.y));
			const double x = e.p.x + t.x * (row - e.p.y) / t.y;
			out.push_back({static_cast<int>(s), static_cast<int>(i), row, x, e.grad});
		}
	return out;
}

std::map<int, std::vector<int>> byRow(const std::vector<Sample>& samples)
{
	std::map<int, std::vector<int>> rows;
	for (size_t i = 0; i < samples.size(); ++i) rows[samples[i].row].push_back(static_cast<int>(i));
	return rows;
}

bool compatible(const Sample& l, const Sample& r, double min_cos)
{
	const double nl = std::hypot(l.grad.x, l.grad.y), nr = std::hypot(r.grad.x, r.grad.y);
	return nl > 0 && nr > 0 && l.grad.dot(r.grad) / (nl * nr) >= min_cos;
}

/** Candidate matches grouped by left sample. */
std::vector<std::vector<Candidate>> candidates(const std::vector<Sample>& L,
                                               const std::vector<Sample>& R, double dmin,
                                               double dmax, const MatchOptions& o)
{
	const auto right_rows = byRow(R);
	const double min_cos = std::cos(o.max_orientation_diff_deg * M_PI / 180);
	std::vector<std::vector<Candidate>> out(L.size());
	for (size_t i = 0; i < L.size(); ++i)
	{
		const auto it = right_rows.find(L[i].row);
		if (it == right_rows.end()) continue;
		for (int j : it->second)
		{
			const double d = L[i].x - R[j].x;
			if (d >= dmin && d <= dmax && compatible(L[i], R[j], min_cos))
				out[i].push_back({static_cast<int>(i), j, d, 0});
		}
	}
	return out;
}

/** Grid of left samples with cell size = support radius. */
using Grid = std::unordered_map<long long, std::vector<int>>;

long long cellKey(int cx, int cy)
{
	return (static_cast<long long>(cy) * 4294967296LL) ^ (cx & 0xffffffffLL); // * 2^32: << of a negative is UB
}

Grid gridOf(const std::vector<Sample>& L, double cell)
{
	Grid g;
	for (size_t i = 0; i < L.size(); ++i)
		g[cellKey(static_cast<int>(std::floor(L[i].x / cell)),
		          static_cast<int>(std::floor(L[i].row / cell)))]
		    .push_back(static_cast<int>(i));
	return g;
}

/** Strongest support one neighbouring left sample gives to candidate @p c. */
double supportFrom(const Candidate& c, const std::vector<Candidate>& nb,
                   const std::vector<Sample>& L, const std::vector<Sample>& R,
                   const MatchOptions& o)
{
	const cv::Point2d cyc((L[c.left].x + R[c.right].x) / 2, L[c.left].row);
	double best = 0;
	for (const auto& n : nb)
	{
		const cv::Point2d cn((L[n.left].x + R[n.right].x) / 2, L[n.left].row);
		const double r = cv::norm(cyc - cn);
		if (r < 1e-6 || r > o.support_radius_px) continue;
		if (std::abs(c.d - n.d) / r < o.disparity_gradient_limit) best = std::max(best, 1.0 / r);
	}
	return best;
}

void computeSupport(std::vector<std::vector<Candidate>>& cand, const std::vector<Sample>& L,
                    const std::vector<Sample>& R, const MatchOptions& o)
{
	const double cell = o.support_radius_px;
	const Grid grid = gridOf(L, cell);
	for (auto& list : cand)
		for (auto& c : list)
		{
			const int cx = static_cast<int>(std::floor(L[c.left].x / cell));
			const int cy = static_cast<int>(std::floor(L[c.left].row / cell));
			for (int dy = -1; dy <= 1; ++dy)
				for (int dx = -1; dx <= 1; ++dx)
				{
					const auto it = grid.find(cellKey(cx + dx, cy + dy));
					if (it == grid.end()) continue;
					for (int j : it->second)
						if (j != c.left) c.support += supportFrom(c, cand[j], L, R, o);
				}
		}
}
}  // namespace

namespace
{
using O = MatchOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& matchOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("disparity_gradient_limit", &O::disparity_gradient_limit, 0.05, 2, kOpt)
	    .number("support_radius_px", &O::support_radius_px, 1, 200, kOpt)
	    .number("max_orientation_diff_deg", &O::max_orientation_diff_deg, 0, 180, kOpt)
	    .number("min_edge_angle_deg", &O::min_edge_angle_deg, 0, 80, kOpt)
	    .number("min_support", &O::min_support, 0, 1, kOpt);
	return b;
}
}  // namespace

void MatchOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                     const std::string& section)
{
	matchOptionsBinder().load(cfg, section, *this);
}

void MatchOptions::dump(std::ostream& out) const
{
	matchOptionsBinder().dump(out, *this);
}

std::vector<EdgeMatch> matchEdgeStrings(const std::vector<EdgeString>& left,
                                        const std::vector<EdgeString>& right, double d_min_px,
                                        double d_max_px, const MatchOptions& o)
{
	const double min_sin = std::sin(o.min_edge_angle_deg * M_PI / 180);
	const auto L = scanlineSamples(left, min_sin), R = scanlineSamples(right, min_sin);
	auto cand = candidates(L, R, d_min_px, d_max_px, o);
	computeSupport(cand, L, R, o);
	std::vector<Candidate> all;
	for (const auto& list : cand) all.insert(all.end(), list.begin(), list.end());
	std::stable_sort(all.begin(), all.end(),
	                 [](auto& a, auto& b) { return a.support > b.support; });
	std::vector<char> used_l(L.size(), 0), used_r(R.size(), 0);
	std::vector<EdgeMatch> out;
	for (const auto& c : all)
	{
		if (c.support < o.min_support || used_l[c.left] || used_r[c.right]) continue;
		used_l[c.left] = used_r[c.right] = 1;
		const Sample& s = L[c.left];
		out.push_back({s.string, s.edgel, s.x, static_cast<double>(s.row), c.d, c.support});
	}
	std::sort(out.begin(), out.end(),
	          [](auto& a, auto& b)
	          { return a.string != b.string ? a.string < b.string : a.edgel < b.edgel; });
	return out;
}

}  // namespace mrolr::stereo
