#include <mrolr/model/AutoCliques.h>
#include <mrolr/recog/ModelTable.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace mrolr::recog
{
namespace
{
std::vector<Eigen::Vector3d> samples(const Feature& f)
{
	if (!f.isLine()) return {f.m};
	std::vector<Eigen::Vector3d> s;
	for (int i = 0; i <= 16; ++i) s.push_back(f.p1 + (f.p2 - f.p1) * (i / 16.0));
	return s;
}

double distinctiveness(const Feature& f)
{
	return f.isLine() ? f.len_mm : 1.5 * f.len_mm;
}

IndexClique cliqueAround(const std::vector<Feature>& fs, size_t focus, int size)
{
	std::vector<std::pair<double, size_t>> near;
	for (size_t j = 0; j < fs.size(); ++j)
	{
		if (j == focus) continue;
		const bool parallel = std::abs(fs[focus].u.dot(fs[j].u)) > std::cos(kParallelAngle);
		near.push_back({featureDistance(fs[focus], fs[j]) + (parallel ? 20.0 : 0.0), j});
	}
	std::sort(near.begin(), near.end());
	IndexClique c{focus, {}};
	for (size_t k = 0; k < near.size() && static_cast<int>(k) + 1 < size; ++k)
		c.members.push_back(near[k].second);
	return c;
}

std::vector<IndexClique> cliquesFromModel(const model::WireFrame& wf,
                                          const std::vector<Feature>& fs)
{
	std::map<int, size_t> index;
	for (size_t i = 0; i < fs.size(); ++i) index[fs[i].id] = i;
	auto at = [&](int id)
	{
		const auto it = index.find(id);
		if (it == index.end())
			throw std::invalid_argument("wire-frame '" + wf.name +
			                            "': clique refers to unknown feature id " +
			                            std::to_string(id));
		return it->second;
	};
	std::vector<IndexClique> out;
	for (const auto& c : wf.cliques)
	{
		IndexClique ic{at(c.focus), {}};
		for (int id : c.members)
			if (id != c.focus) ic.members.push_back(at(id));
		out.push_back(ic);
	}
	return out;
}
}  // namespace

double featureDistance(const Feature& a, const Feature& b)
{
	double best = 1e300;
	for (const auto& p : samples(a))
		for (const auto& q : samples(b)) best = std::min(best, (p - q).norm());
	return best;
}

std::vector<IndexClique> chooseCliques(const std::vector<Feature>& features, int count, int size)
{
	std::vector<size_t> order(features.size());
	std::iota(order.begin(), order.end(), 0);
	std::stable_sort(order.begin(), order.end(),
	                 [&](size_t i, size_t j)
	                 { return distinctiveness(features[i]) > distinctiveness(features[j]); });
	std::vector<IndexClique> out;
	for (size_t k = 0; k < order.size() && static_cast<int>(k) < count; ++k)
		out.push_back(cliqueAround(features, order[k], size));
	return out;
}

std::vector<IndexClique> ModelTable::automaticCliques(const model::WireFrame& wf,
                                                      const std::string& method, int count,
                                                      int size) const
{
	if (method == "recog") return chooseCliques(features_, count, size);
	if (method != "model")
		throw std::invalid_argument("unknown automatic clique method '" + method +
		                            "' (recog | model)");
	model::WireFrame withCliques = wf;
	model::CliqueOptions co;
	co.clique_size = size;
	co.max_cliques = count;
	model::addAutomaticCliques(withCliques, co);
	return cliquesFromModel(withCliques, features_);
}

ModelTable::ModelTable(const model::WireFrame& wf, int auto_count, int auto_size,
                       const std::string& auto_method, const std::string& file_cliques)
    : name_(wf.name), features_(featuresOf(wf)), n_(features_.size())
{
	if (features_.size() < 2)
		throw std::invalid_argument("wire-frame '" + wf.name +
		                            "' has fewer than two lines and conics to match");
	if (file_cliques != "use" && file_cliques != "add" && file_cliques != "ignore")
		throw std::invalid_argument("unknown file clique use '" + file_cliques +
		                            "' (use | add | ignore)");
	automatic_ = wf.cliques.empty() || file_cliques == "ignore";
	if (!automatic_) cliques_ = cliquesFromModel(wf, features_);
	if (automatic_ || file_cliques == "add")
		for (auto& c : automaticCliques(wf, auto_method, auto_count, auto_size))
			cliques_.push_back(std::move(c));
	table_.resize(n_ * n_);
	for (size_t i = 0; i < n_; ++i)
		for (size_t j = 0; j < n_; ++j)
			if (i != j) table_[i * n_ + j] = relateModel(features_[i], features_[j]);
	for (const auto& f : features_) total_len_mm_ += f.len_mm;
}

}  // namespace mrolr::recog
