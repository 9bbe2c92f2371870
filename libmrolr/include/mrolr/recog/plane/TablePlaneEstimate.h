#pragma once
/** The table top the objects stand on, estimated from one stereo scene (robot side, no truth).
 *
 * The head's kinematics give the up direction in the scene frame (C0 stands level on the base);
 * the robot's plan gives the table's height roughly. The scene's horizontal lines and horizontal
 * conics (the table's front edge, the objects' bottom edges and rims) within window_mm of an
 * expected height are candidate heights; each is scored by the length of the horizontal features
 * at it plus the length of the vertical features that stand on it (the objects' sides and limbs,
 * whose lower ends lie on the top), less the length of those whose upper ends lie at it (an
 * object's top, a leg under the slab). Only heights with sides rising stand_min_mm from them
 * compete when there are any (the objects stand on the table; the slab's lower edge carries
 * nothing), and the lowest of them that scores at least lower_share of their best is the top (the
 * objects' lids lie above it). The height is refined by a weighted least
 * mean of its features' heights; with fit_normal, by a weighted least squares plane through their
 * points, whose normal is kept only when the features span the plane in two directions and it
 * lies within max_tilt_deg of up. Lengths mm. */
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/plane/SupportPlane.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mrolr::recog
{
struct TablePlaneOptions
{
	double window_mm = 60;            ///< candidate heights this close to an expected one
	double horizontal_tol_deg = 4;    ///< a line this close to horizontal lies in a plane of up
	double vertical_tol_deg = 10;     ///< a line this close to up is a side standing on the top
	double cluster_mm = 4;            ///< features at one height: this close to it
	double stand_tol_mm = 8;          ///< a side stands on the top when its lower end is this close
	double stand_min_mm = 35;         ///< …and it rises this far (more than a 30 mm table slab)
	double lower_share = 0.5;         ///< a lower height with standing sides wins at this share
	double min_line_mm = 20;          ///< shorter lines are left out
	/** Fit the normal too (a table not level with the base); off: the normal is up, which the
	 * head's kinematics give better than a few table edges do. */
	bool fit_normal = false;
	double max_tilt_deg = 2;          ///< a fitted normal further from up is not kept
};

struct TablePlaneEstimate
{
	bool found = false;
	SupportPlane plane;         ///< in the scene frame (mm), normal up
	double support_mm = 0;      ///< the score of the chosen height (feature length, mm)
	int horizontal = 0;         ///< horizontal features at the chosen height
	int standing = 0;           ///< vertical features standing on it
	bool normal_fitted = false; ///< the normal is the fitted one, not up
	std::string reason;         ///< why none was found
};

/** @p up_S: unit up direction in the scene frame; @p expected_heights_mm: signed heights along
 * up of the table tops the robot expects (scene origin at 0), e.g. from its plan. */
TablePlaneEstimate estimateTablePlane(const model::WireFrame& scene_S, const Eigen::Vector3d& up_S,
                                      const std::vector<double>& expected_heights_mm,
                                      const TablePlaneOptions& o = {});

}  // namespace mrolr::recog
