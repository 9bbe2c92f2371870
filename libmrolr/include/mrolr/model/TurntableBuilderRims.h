#pragma once
/** Circles from the union of arcs of all turntable views (thesis 6.1, B.2.1). One view sees only
 * the front of a rim, and its conic fitted to that short arc can have its centre and radius far off
 * (the bottle's shoulder: a = 25, b = 11 mm for a 35 mm circle), so that neither merging (equal
 * centre and size) nor the support of other views keeps it. The arcs of several views of one rim
 * lie on the same 3D circle in frame O, so a circle is fitted to the samples of all views' arcs
 * together: RANSAC on three samples of conic arcs, then a least-squares plane and circle through
 * the inliers (within `rim_tol_mm`, tangent within `rim_max_tangent_deg`). A circle is kept when
 * its inliers come from `rim_min_views` views and its conic samples cover `rim_min_arc_deg` of it;
 * single-view features lying on it are replaced by it. No centre (turntable axis), plane or radius
 * is assumed: handles in vertical planes and off-axis rims are found the same way. */

#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>
#include <vector>

namespace mrolr::model
{
/** Options ([turntable] keys `rim_*` of config/model.ini). */
struct RimOptions
{
	bool enabled = true;          ///< rim_fit
	double tol_mm = 1.0;          ///< inlier: distance to the circle
	double max_tangent_deg = 20;  ///< inlier: tangent against the circle's
	double min_arc_deg = 120;     ///< conic inliers must cover this much of the circle
	int min_views = 3;            ///< inliers from this many views
	double min_radius_mm = 5, max_radius_mm = 150;
	double consume_fraction = 0.6;  ///< a feature this much on a kept circle is replaced by it
	int iterations = 3000;          ///< RANSAC hypotheses per circle (fixed seed: reproducible)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	/** Writes the keys and values as loadFromConfigFile reads them. */
	void dump(std::ostream& out) const;
};

/** Finds circles seen across @p views (frame O) and removes the single-view features that lie on
 * them; returns the circles (full or partial arcs, ids 0). */
std::vector<Conic3> fitRimsAcrossViews(std::vector<WireFrame>& views, const RimOptions& o);

}  // namespace mrolr::model
