#include <mrolr/model/AutoCliques.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace mrolr::model
{
namespace
{
/** What the chooser needs of one feature. */
struct Info
{
	int id = 0;
	Eigen::Vector3d mid = Eigen::Vector3d::Zero();
	double score = 0;
};

std::vector<Info> featureInfo(const WireFrame& wf, double conic_weight)
{
	std::vector<Info> out;
	for (const auto& l : wf.lines) out.push_back({l.id, (l.p1 + l.p2) / 2, l.length()});
	for (const auto& c : wf.conics) out.push_back({c.id, c.centre, conic_weight * arcLength(c)});
	return out;
}

Eigen::Vector3d centroid(const std::vector<Info>& f)
{
	Eigen::Vector3d c = Eigen::Vector3d::Zero();
	for (const auto& x : f) c += x.mid;
	return f.empty() ? c : Eigen::Vector3d(c / static_cast<double>(f.size()));
}

bool faces(const Info& f, const Eigen::Vector3d& c, const Eigen::Vector3d& v, double margin)
{
	return (f.mid - c).dot(v) >= -margin;
}

/** Does direction v see every member of clique @p k? */
bool sees(const Clique& k, const std::map<int, Info>& by_id, const Eigen::Vector3d& c,
          const Eigen::Vector3d& v, double margin)
{
	auto ok = [&](int id)
	{
		const auto it = by_id.find(id);
		return it != by_id.end() && faces(it->second, c, v, margin);
	};
	return ok(k.focus) && std::all_of(k.members.begin(), k.members.end(), ok);
}

/** Focus plus its nearest visible neighbours, focus last. */
Clique cliqueAround(const Info& focus, std::vector<Info> visible, int size)
{
	std::sort(visible.begin(), visible.end(),
	          [&](const Info& a, const Info& b)
	          { return (a.mid - focus.mid).squaredNorm() < (b.mid - focus.mid).squaredNorm(); });
	Clique k{focus.id, {}};
	for (const auto& f : visible)
		if (f.id != focus.id && static_cast<int>(k.members.size()) < size - 1)
			k.members.push_back(f.id);
	k.members.push_back(focus.id);
	return k;
}
}  // namespace

namespace
{
using C = CliqueOptions;
constexpr auto kOpt = util::Presence::Optional;  // [cliques]: every key of config/model.ini

const util::OptionsBinder<C>& cliqueOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<C>()
	        .integer("clique_size", &C::clique_size, 2, 100, kOpt)
	        .integer("max_cliques", &C::max_cliques, 0, 1000000, kOpt)
	        .integer("azimuths", &C::azimuths, 1, 360, kOpt)
	        .numbers("elevations_deg", &C::elevations_deg, 0, -90, 90, kOpt)  // any count
	        .number("conic_weight", &C::conic_weight, 0, 1000, kOpt)
	        .number("facing_margin_mm", &C::facing_margin_mm, 0, 1e6, kOpt);
	return b;
}
}  // namespace

void CliqueOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	cliqueOptionsBinder().load(cfg, section, *this);
}

std::vector<Eigen::Vector3d> viewingDirections(const CliqueOptions& o)
{
	std::vector<Eigen::Vector3d> out;
	for (double el : o.elevations_deg)
		for (int k = 0; k < o.azimuths; ++k)
		{
			const double az = 2 * M_PI * k / o.azimuths, e = el * M_PI / 180;
			out.emplace_back(std::cos(e) * std::cos(az), std::cos(e) * std::sin(az), std::sin(e));
		}
	return out;
}

std::vector<size_t> uncoveredDirections(const WireFrame& wf, const CliqueOptions& o)
{
	const auto info = featureInfo(wf, o.conic_weight);
	std::map<int, Info> by_id;
	for (const auto& f : info) by_id[f.id] = f;
	const Eigen::Vector3d c = centroid(info);
	const auto dirs = viewingDirections(o);
	std::vector<size_t> out;
	for (size_t d = 0; d < dirs.size(); ++d)
		if (std::none_of(wf.cliques.begin(), wf.cliques.end(),
		                 [&](const Clique& k)
		                 { return sees(k, by_id, c, dirs[d], o.facing_margin_mm); }))
			out.push_back(d);
	return out;
}

int addAutomaticCliques(WireFrame& wf, const CliqueOptions& o)
{
	auto info = featureInfo(wf, o.conic_weight);
	std::sort(info.begin(), info.end(), [](auto& a, auto& b) { return a.score > b.score; });
	const Eigen::Vector3d c = centroid(info);
	const auto dirs = viewingDirections(o);
	int added = 0;
	for (auto todo = uncoveredDirections(wf, o);
	     !todo.empty() && static_cast<int>(wf.cliques.size()) < o.max_cliques;
	     todo = uncoveredDirections(wf, o))
	{
		const Eigen::Vector3d v = dirs[todo.front()];
		std::vector<Info> visible;
		for (const auto& f : info)
			if (faces(f, c, v, o.facing_margin_mm)) visible.push_back(f);
		if (visible.empty()) break;  // nothing faces this way: cannot be covered
		wf.cliques.push_back(cliqueAround(visible.front(), visible, o.clique_size));
		++added;
	}
	return added;
}

}  // namespace mrolr::model
