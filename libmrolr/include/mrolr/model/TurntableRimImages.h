#pragma once
/** Completing the arcs of horizontal rims from the views' images (docs/model.md). A rim
 * found across views (fitRimsAcrossViews) keeps the arc its 3D inliers cover, but a rim between
 * two surfaces of similar grey has an image edge on part of its width only (the bottle's shoulder:
 * its lit third), and the stereo reconstruction of that part is a short, badly fitted conic in
 * some views and nothing in others. The circle itself is fixed by the views that did reconstruct
 * it; the rest of its arc is then checked in the images: a 10° piece of the circle is added when,
 * in some view that faces it (its outward radial direction towards the camera), its projection
 * lies on image edges (imageEdgeShare). Only rims whose plane is horizontal in frame O (the
 * turntable's axis is z) are completed: a handle's arc in a vertical plane ends at the body. */

#include <mrolr/model/TurntableBuilderImages.h>
#include <mrolr/model/WireFrame.h>

#include <vector>

namespace mrolr::model
{
/** Options ([turntable] rim_image_* keys). */
struct RimImageOptions
{
	double min_gradient = 0;    ///< rim_image_gradient: Sobel |∇I| on the projection (0 = off)
	double min_fraction = 0.8;  ///< rim_image_min_fraction: samples of a piece on edges
	double max_tilt_deg = 10;   ///< rim_image_max_tilt_deg: rim normal from O's z axis
	double min_facing_cos = 0.3;  ///< a view faces a piece when radial·(camera − p)/|..| exceeds it
};

/** Extends the arc of every horizontal circle of @p rims (a = b, frame O) by the 10° pieces that
 * some view of @p edges shows as image edges; the arc is the circle minus its largest piece that
 * neither the arc nor the images cover. Returns the number of pieces added. */
int completeRimsFromImages(std::vector<Conic3>& rims, const std::vector<ViewEdges>& edges,
                           const RimImageOptions& o);

/** Number of the 36 10° pieces of circle @p c (whole circle, its arc ignored) that some view of
 * @p edges facing the piece shows as image edges; sets @p c's arc to the circle minus its largest
 * run of pieces not shown (an empty arc t1 = t2 when none is shown). */
int arcFromImages(Conic3& c, const std::vector<ViewEdges>& edges, const RimImageOptions& o);

/** Mean image gradient (grey levels/px, at the projected pixel) along the whole circle @p c, over
 * the views of @p edges facing each 10° piece: how sharply the images show the circle. */
double meanFacingGradient(const Conic3& c, const std::vector<ViewEdges>& edges,
                          const RimImageOptions& o);

}  // namespace mrolr::model
