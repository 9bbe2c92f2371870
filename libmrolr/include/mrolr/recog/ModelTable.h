#pragma once
/** A model prepared for matching: its features, the table of pairwise relations of every ordered
 * pair (thesis 6.3.1, "build pairwise geometric tables", computed once per model) and its cliques —
 * the model's own `clique` lines or, when it has none, cliques chosen automatically. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/PairRelation.h>

#include <string>
#include <vector>

namespace mrolr::recog
{
/** A clique as indices into ModelTable::features: the focus and its other members. */
struct IndexClique
{
	size_t focus = 0;
	std::vector<size_t> members;  ///< focus excluded
};

/** Automatic cliques: the @p count most distinctive features (longest lines, conic arcs counted
 * 1.5 times their length) become foci, each with its @p size - 1 nearest features (segment-to-
 * segment distance, lines parallel to the focus ranked 20 mm further because they constrain the
 * pose less). Measured on the synthetic table scenes it recognises more than the model area's
 * viewing-direction cliques (docs/recog.md), so it is the default for models without cliques. */
std::vector<IndexClique> chooseCliques(const std::vector<Feature>& features, int count, int size);

/** Minimum distance between two features (segments sampled at 17 points; conics at their arcs'
 * centres), mm. */
double featureDistance(const Feature& a, const Feature& b);

class ModelTable
{
 public:
	/** Prepares @p wf. Uses its cliques if it has any (ids must exist: std::invalid_argument
	 * otherwise), else automatic ones: @p auto_method "recog" is chooseCliques(features,
	 * auto_count, auto_size); "model" is the model area's viewing-direction coverage
	 * (model::addAutomaticCliques, what `mrolr-model cliques` writes). @p file_cliques: "use"
	 * the file's cliques as said, "add" the automatic ones to them, "ignore" them. */
	ModelTable(const model::WireFrame& wf, int auto_count, int auto_size,
	           const std::string& auto_method = "recog", const std::string& file_cliques = "use");

	const std::string& name() const { return name_; }
	const std::vector<Feature>& features() const { return features_; }
	const std::vector<IndexClique>& cliques() const { return cliques_; }
	bool cliquesAreAutomatic() const { return automatic_; }
	/** Relation of feature j seen from feature i (precomputed). */
	const PairRelation& relation(size_t i, size_t j) const { return table_[i * n_ + j]; }
	/** Sum of feature lengths (mm): the denominator of the verification score. */
	double totalLength() const { return total_len_mm_; }

 private:
	std::vector<IndexClique> automaticCliques(const model::WireFrame& wf, const std::string& method,
	                                          int count, int size) const;

	std::string name_;
	std::vector<Feature> features_;
	std::vector<IndexClique> cliques_;
	std::vector<PairRelation> table_;
	size_t n_ = 0;
	bool automatic_ = false;
	double total_len_mm_ = 0;
};

}  // namespace mrolr::recog
