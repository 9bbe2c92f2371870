#pragma once
/** Horizontal rims from straight chords (docs/model.md). A small rim between two surfaces
 * (the bottle's neck base) projects in every view as a flat ellipse that the stereo reconstruction
 * returns as one or two straight, nearly horizontal segments, never as an arc, so that
 * fitRimsAcrossViews has nothing to fit. Each such chord still spans the rim's width as seen from
 * its view: its ends lie at the rim's extremes across the viewing direction. With the turntable's
 * axis (z of frame O) as the rim's normal, a circle at height z with centre (cx, cy) and radius r
 * seen along horizontal direction d spans c·e ± r across it (e = z × d); the chords of several
 * views at one height give these spans. Only the spans across the view are used: the depth of a
 * horizontal image segment is the least certain part of its stereo reconstruction. The spans are
 * cut short on the unlit side, so they give the circle's height, a first centre and a lower bound
 * on its radius only; a box's edges give spans that disagree (`rim_chord_span_tol_mm`). Centre,
 * height and radius are then searched near these in the views' images: the circle kept is the
 * sharpest (meanFacingGradient) of those the images show over `rim_chord_min_image_arc_deg`
 * (arcFromImages), with the arc they show. */

#include <mrolr/model/TurntableRimImages.h>
#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace mrolr::model
{
/** Options ([turntable] keys `rim_chord_*` of config/model.ini). */
struct RimChordOptions
{
	int min_views = 3;              ///< rim_chord_min_views: chords from this many views (0 = off)
	double max_slope_deg = 8;       ///< rim_chord_max_slope_deg: chord within this of horizontal
	double height_tol_mm = 3;       ///< rim_chord_height_tol_mm: chords at one height
	double tol_mm = 2;              ///< rim_chord_tol_mm: centre searched this far (1 mm steps)
	double min_image_arc_deg = 300; ///< rim_chord_min_image_arc_deg: shown by the images
	double span_tol_mm = 5;         ///< rim_chord_span_tol_mm: spans' middles and widths agree
	double max_radius_ratio = 2;    ///< rim_chord_max_radius_ratio: radius up to this × half span
	double min_radius_mm = 5, max_radius_mm = 150;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/** Finds horizontal rims from the chords of @p views (frame O; @p edges the views' left images, one
 * per view, in the same order) that no circle of @p known already is (same height and radius
 * within height_tol_mm) and returns the rims (ids 0); the chords stay for the support step. */
std::vector<Conic3> rimsFromChords(const std::vector<WireFrame>& views,
                                   const std::vector<ViewEdges>& edges,
                                   const std::vector<Conic3>& known, const RimChordOptions& o,
                                   const RimImageOptions& image_options);

}  // namespace mrolr::model
