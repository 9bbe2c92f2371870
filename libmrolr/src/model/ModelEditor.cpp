#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/WireFrameSampling.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <set>
#include <stdexcept>

namespace mrolr::model
{
namespace
{
bool inBox(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
	return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

template <typename T, typename Pred>
size_t eraseIf(std::vector<T>& v, Pred pred)
{
	const size_t before = v.size();
	v.erase(std::remove_if(v.begin(), v.end(), pred), v.end());
	return before - v.size();
}
}  // namespace

void listFeatures(const WireFrame& wf, std::ostream& out)
{
	for (const auto& l : wf.lines)
		out << "line " << l.id << ' ' << l.p1.transpose() << "  " << l.p2.transpose() << "  len_mm "
		    << l.length() << '\n';
	for (const auto& c : wf.conics)
		out << "conic " << c.id << " centre " << c.centre.transpose() << " normal "
		    << c.normal.transpose() << " a " << c.a << " b " << c.b << " arc_deg "
		    << (c.t2 - c.t1) * 180 / M_PI << '\n';
	if (wf.has_grasp)
		out << "grasp " << wf.grasp.p_mm.transpose() << " yaw/pitch/roll_deg " << wf.grasp.yaw_deg
		    << ' ' << wf.grasp.pitch_deg << ' ' << wf.grasp.roll_deg << '\n';
	for (const auto& c : wf.cliques)
		out << "clique focus " << c.focus << " size " << c.members.size() << '\n';
}

size_t removeIds(WireFrame& wf, const std::vector<int>& ids)
{
	const std::set<int> gone(ids.begin(), ids.end());
	for (int id : gone)
	{
		const bool found =
		    std::any_of(wf.lines.begin(), wf.lines.end(), [&](auto& l) { return l.id == id; }) ||
		    std::any_of(wf.conics.begin(), wf.conics.end(), [&](auto& c) { return c.id == id; });
		if (!found) throw std::invalid_argument("no feature with id " + std::to_string(id));
	}
	size_t n = eraseIf(wf.lines, [&](const Line3& l) { return gone.count(l.id) > 0; });
	n += eraseIf(wf.conics, [&](const Conic3& c) { return gone.count(c.id) > 0; });
	pruneCliques(wf);
	return n;
}

size_t removeInBox(WireFrame& wf, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
	size_t n = eraseIf(wf.lines,
	                   [&](const Line3& l) { return inBox(l.p1, lo, hi) && inBox(l.p2, lo, hi); });
	n += eraseIf(wf.conics,
	             [&](const Conic3& c)
	             {
		             const auto s = sampleConic(c, 5.0, 0);
		             return std::all_of(s.begin(), s.end(),
		                                [&](auto& q) { return inBox(q.p, lo, hi); });
	             });
	pruneCliques(wf);
	return n;
}

int addLine(WireFrame& wf, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2)
{
	if ((p2 - p1).norm() <= 0) throw std::invalid_argument("a line needs two distinct endpoints");
	const int id = maxId(wf) + 1;
	wf.lines.push_back({id, p1, p2});
	return id;
}

int addConic(WireFrame& wf, Conic3 c)
{
	if (c.normal.norm() < 1e-9 || c.major.norm() < 1e-9)
		throw std::invalid_argument("conic normal and major axis must be non-zero");
	c.normal.normalize();
	c.major.normalize();
	if (std::abs(c.normal.dot(c.major)) > 1e-6)
		throw std::invalid_argument("conic major axis is not in its plane");
	if (!(c.b > 0) || c.a < c.b)
		throw std::invalid_argument("conic semi-axes must satisfy a >= b > 0");
	if (!(c.t2 > c.t1)) throw std::invalid_argument("conic arc needs t1 < t2");
	c.id = maxId(wf) + 1;
	wf.conics.push_back(c);
	return c.id;
}

void setGrasp(WireFrame& wf, const Eigen::Vector3d& p_mm, double yaw_deg, double pitch_deg,
              double roll_deg)
{
	wf.has_grasp = true;
	wf.grasp = {p_mm, yaw_deg, pitch_deg, roll_deg};
}

void pruneCliques(WireFrame& wf)
{
	std::set<int> ids;
	for (const auto& l : wf.lines) ids.insert(l.id);
	for (const auto& c : wf.conics) ids.insert(c.id);
	eraseIf(wf.cliques,
	        [&](const Clique& c)
	        {
		        return !ids.count(c.focus) || std::any_of(c.members.begin(), c.members.end(),
		                                                  [&](int m) { return !ids.count(m); });
	        });
}

}  // namespace mrolr::model
