#pragma once
/** Rims seen edge-on between two silhouettes (docs/model.md step 10). A horizontal rim
 * whose plane passes near the camera (the bottle's shoulder and neck rims seen from the head's
 * height) images as a straight piece along the rows between the body's two silhouettes: no
 * ellipse to pair, no depth along it, and its back-projection onto a horizontal plane is
 * degenerate. Its ends, though, are the rim's tangent points on the silhouettes, whose 3D lines
 * the stereo has: the chord between the two tangent points is horizontal and at right angles to
 * the horizontal viewing direction, and the circle through them has its centre r²/D behind the
 * chord's middle (D the horizontal distance from the camera). A circle is kept when the piece's
 * edgels lie within max_residual_px (RMS) of its image. A box's top edge between its two vertical
 * edges passes only when the face is seen square on (the chord test) and its top is seen
 * edge-on. */

#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::stereo
{
/** Options of the edge-on rim step ([scene] edge_on_rim* keys). */
struct EdgeOnRimOptions
{
	bool enabled = false;           ///< [scene] edge_on_rims (needs the up direction)
	double max_image_deg = 12;      ///< the rim's image piece within this of the rows
	double corner_radius_px = 6;    ///< a silhouette's image passes this near the piece's end
	double max_extension_px = 30;   ///< ... or meets the piece's line this far beyond the end
	double min_steepness = 0.5;     ///< |direction · up| of a silhouette's 3D line
	double max_chord_tilt_deg = 8;  ///< the tangent chord's angle to the horizontal plane
	double max_chord_view_cos = 0.1;  ///< |cos| of the chord's angle to the viewing direction
	double max_residual_px = 2;     ///< RMS image distance of the piece's edgels from the circle
	double min_radius_mm = 5, max_radius_mm = 150;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Circles (normal up_L, mm in L) of the left line pieces along the rows that end on two steep 3D
 * @p lines (the silhouettes), not already covered by a conic of @p existing (centre within half
 * the radius, radius within 20 %). */
std::vector<ConicFit3> edgeOnRims(const std::vector<EdgeString>& left_strings,
                                  const std::vector<ImagePiece>& left_pieces,
                                  const std::vector<LineFit3>& lines,
                                  const std::vector<ConicFit3>& existing,
                                  const Eigen::Vector3d& up_L, const Rectifier& rect,
                                  const EdgeOnRimOptions& o);

}  // namespace mrolr::stereo
