#pragma once
/** The model editor of thesis 6.2 as functions on a WireFrame: list, remove by id or region, add a
 * line or conic, merge duplicated segments, set the grasp point. Every edit keeps ids unique and
 * drops cliques that name a removed feature. */

#include <mrolr/model/WireFrame.h>

#include <Eigen/Core>

#include <iosfwd>
#include <vector>

namespace mrolr::model
{
/** Tolerances deciding that two features are the same edge seen twice (turntable views, 6.1). */
struct MergeOptions
{
	double max_distance_mm = 4;     ///< lines: each overlap point within this of the other line
	double max_angle_deg = 6;       ///< lines: directions; conics: plane normals
	double max_gap_mm = 2;          ///< collinear lines closer than this end to end are joined too
	double max_centre_mm = 5;       ///< conics: centre distance
	double max_radius_diff_mm = 4;  ///< conics: semi-axis difference
};

/** One line per feature: "line ID x1 y1 z1 x2 y2 z2 len_mm" / "conic ID ... a b arc_deg". */
void listFeatures(const WireFrame& wf, std::ostream& out);

/** Removes the features with these ids; returns how many were removed. Unknown ids throw
 * std::invalid_argument naming the id. */
size_t removeIds(WireFrame& wf, const std::vector<int>& ids);

/** Removes every feature lying entirely inside the axis-aligned box [lo, hi] (mm). */
size_t removeInBox(WireFrame& wf, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/** Adds a line; returns its new id (max id + 1). Throws for a zero-length line. */
int addLine(WireFrame& wf, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2);

/** Adds a conic (normal and major are normalised; major must be ⟂ normal, a >= b > 0, t1 < t2);
 * returns its new id. Throws std::invalid_argument for a malformed conic. */
int addConic(WireFrame& wf, Conic3 conic);

/** Sets the grasp point (mm) and orientation (degrees). */
void setGrasp(WireFrame& wf, const Eigen::Vector3d& p_mm, double yaw_deg, double pitch_deg,
              double roll_deg);

/** Merges duplicated features: collinear overlapping (or nearly touching) lines become one line
 * spanning both; concentric coplanar conics of equal size become one conic whose arc covers both.
 * Repeats until nothing merges. Returns the number of features removed. */
size_t mergeDuplicates(WireFrame& wf, const MergeOptions& options = {});

/** Are @p a and @p b the same edge by the tolerances of @p options (see mergeDuplicates)? */
bool isDuplicate(const Line3& a, const Line3& b, const MergeOptions& options);
bool isDuplicate(const Conic3& a, const Conic3& b, const MergeOptions& options);

/** Drops cliques that name an id no longer present. */
void pruneCliques(WireFrame& wf);

}  // namespace mrolr::model
