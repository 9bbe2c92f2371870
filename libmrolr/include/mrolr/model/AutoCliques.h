#pragma once
/** Automatic choice of focus features and cliques (thesis 7.1.1, fig 7.1.12, chose them by hand).
 * Distinctive features are long lines and conics (a conic's arc length counts conic_weight times);
 * a clique is a focus feature and its nearest neighbours (by midpoint distance) among the features
 * facing the same viewing direction. Viewing directions are sampled around the object (azimuths ×
 * elevations in the object frame, z up); a feature faces a direction v when its midpoint lies on
 * the camera side of the model's centroid, (m − centroid)·v >= −facing_margin_mm. Cliques are added
 * until every direction sees at least one whole clique. Manual cliques already in the model count
 * towards the coverage and are kept. */

#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace mrolr::model
{
struct CliqueOptions
{
	int clique_size = 6;  ///< features per clique, focus included
	int max_cliques = 12;
	int azimuths = 8;  ///< viewing directions around z
	std::vector<double> elevations_deg{20, 50};
	double conic_weight = 1.5;
	double facing_margin_mm = 5;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/** Unit viewing directions (object to camera) used for coverage. */
std::vector<Eigen::Vector3d> viewingDirections(const CliqueOptions& o);

/** Adds automatic cliques to @p wf (keeping its manual ones); returns how many were added. Members
 * list the neighbours first and the focus last, as in fig 7.1.12. */
int addAutomaticCliques(WireFrame& wf, const CliqueOptions& options = {});

/** Viewing directions (indices into viewingDirections) from which no whole clique is visible. */
std::vector<size_t> uncoveredDirections(const WireFrame& wf, const CliqueOptions& options = {});

}  // namespace mrolr::model
