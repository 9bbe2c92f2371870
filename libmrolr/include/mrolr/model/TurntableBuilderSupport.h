#pragma once
/** Which single-view features of a turntable build are real edges of the object (thesis 6.1,
 * B.2.1). A fixed 3D edge is seen at the same place (frame O) from several views. An occluding
 * contour (the silhouette of an upright cylinder, cone or bottle neck) is not fixed to the object:
 * it turns with the viewing direction, so the neighbouring views (45°, 90° away) see other
 * generators of the surface there, and only the view from the opposite side (180°) sees a contour
 * near the same place. Such contour generators of upright surfaces of revolution run steeply (along
 * the turntable axis), so steep pieces are supported only by views turned at most
 * `support_max_view_angle_deg`; other pieces by any view (edges running across the viewing
 * direction lie along the scanlines of the views 90° away and are often seen only from opposite
 * sides). Support is counted point by point along the feature, so that a conic arc can be
 * supported by another view's line pieces of the same edge and the other way round. */

#include <mrolr/model/TurntableBuilderImages.h>
#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>
#include <vector>

namespace mrolr::model
{
/** Options of the view support test ([turntable] keys `support_*` of config/model.ini). */
struct ViewSupportOptions
{
	double tol_mm = 4;            ///< a sample is supported by a sample of another view this near
	double max_tangent_deg = 20;  ///< ... whose tangent is within this angle
	double max_view_angle_deg = 90;  ///< steep pieces: only views turned at most this far count
	double steep_max_deg = 45;       ///< a piece is steep when this near to O's z axis (deg)
	double image_min_gradient = 8;   ///< image edge: Sobel |∇I| at least this (grey levels/px)
	double min_fraction = 0.5;       ///< of a feature's length supported by one supporting view
	int min_views = 2;               ///< views seeing a feature, its own included

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	/** Writes the keys and values as loadFromConfigFile reads them. */
	void dump(std::ostream& out) const;
};

/** Smallest angle (deg, 0..180) between two turntable angles (deg). */
double turntableAngleBetween(double a_deg, double b_deg);

/** How many views other than @p own (in @p angles_deg order, frame O) support @p wf's feature
 * index @p feature (line index, then lines.size() + conic index) over min_fraction of its length.
 */
int supportingViews(const std::vector<WireFrame>& views, const std::vector<double>& angles_deg,
                    size_t own, size_t feature, const ViewSupportOptions& o);

/** Removes from every view the features that fewer than min_views views (the own included) see;
 * the views are in frame O, @p angles_deg their turntable angles. A feature whose steep pieces only
 * far views see is kept when @p edges (the views' left images, empty: none) show an edge along them
 * in a near view, over min_fraction of their length. Returns how many features were removed. */
size_t keepFeaturesSeenFromNearViews(std::vector<WireFrame>& views,
                                     const std::vector<double>& angles_deg,
                                     const ViewSupportOptions& o,
                                     const std::vector<ViewEdges>& edges = {});

}  // namespace mrolr::model
