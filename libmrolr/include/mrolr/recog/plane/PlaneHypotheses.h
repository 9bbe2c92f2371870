#pragma once
/** Pose hypotheses from single scene features on the support plane (beyond the thesis).
 *
 * The clique matcher (thesis 6.3) needs 3–5 mutually consistent scene features of one object; on
 * reconstructed table scenes stereo often recovers too little of an object for that, although the
 * images support its true pose well. Objects stand upright on a known plane (the table top,
 * SupportPlane.h), which leaves 3 of the 6 pose parameters free (position on the plane and yaw):
 * - a model rim (a conic whose normal is near the model's +z) matched to a scene conic whose
 *   normal is near the plane's normal, of the same radius and at the rim's height above the plane,
 *   fixes the position (the model's axis through the scene centre, its base on the plane); the yaw
 *   is tried every rim_yaw_step_deg;
 * - a horizontal model line matched to a horizontal scene line at its height above the plane
 *   fixes the yaw (both senses) and the line's lateral offset; along the line the scene segment
 *   (a fragment) is aligned start to start, end to end and middle to middle;
 * - a cylinder of the model (a frustum of a body of revolution, Limbs.h, of nearly constant
 *   radius r) matched to a scene line along the plane's normal at heights within the cylinder's:
 *   the line is a limb, where the sight rays graze the side, so the axis is r from it,
 *   perpendicular to the plane through the camera centre and the line (either side of the line);
 *   the yaw is tried every rim_yaw_step_deg. Stereo finds limbs where it finds no rim: the
 *   outline of a bottle against the table is its strongest edge. The camera centre is the origin
 *   of S (S is the left camera frame L for the head's scenes);
 * - two of the model's vertical edges matched to two scene lines along the plane's normal as far
 *   apart (horizontally) fix the yaw and the position (either assignment), for models without
 *   cylinders (boxes): stereo recovers a box's vertical edges, which cross the epipolar lines,
 *   where it misses its horizontal ones against a wall of similar brightness.
 * Every hypothesis stands on the plane with the model's +z along the plane's normal. They are
 * judged in the images (Recognizer): the 3D score cannot tell them apart, a single feature being
 * all they have in common with the scene. Millimetres; model frame O, scene frame S. */

#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Feature.h>
#include <mrolr/recog/plane/PlaneHypothesisOptions.h>
#include <mrolr/recog/plane/SupportPlane.h>

#include <Eigen/Geometry>

#include <vector>

namespace mrolr::recog
{
/** One hypothesis and what made it. */
struct PlaneHypothesis
{
	Eigen::Isometry3d T_OinS = Eigen::Isometry3d::Identity();
	bool from_rim = false;        ///< a rim match
	bool from_limb = false;       ///< a limb match
	bool from_edge_pair = false;  ///< a vertical edge pair (none of the three: a horizontal line)
	int model_feature = 0;        ///< index into the model's features
	int scene_feature = 0;        ///< index into the scene's features
};

/** The lowest z (mm) of the model's edges (model::sampleWireFrame every 2 mm): its base, which
 * stands on the support plane (0 for models in the object frame O of docs/model.md, up to the
 * model building's noise). */
double modelBaseZ_mm(const model::WireFrame& model_O);

/** A cylinder of a model for limb hypotheses: its axis (model frame; parallel to +z within
 * rim_normal_tol_deg) through (axis_x_mm, axis_y_mm), radius r_mm, from z_lo_mm to z_hi_mm
 * (model z). */
struct LimbCylinder
{
	double axis_x_mm = 0, axis_y_mm = 0, r_mm = 0, z_lo_mm = 0, z_hi_mm = 0;
};

/** Two vertical edges of a model (model frame, mm): their points in the xy plane, their z range
 * (the lower of the two ends and the higher), their horizontal distance. */
struct VerticalEdgePair
{
	size_t i = 0, j = 0;  ///< model feature indices
	Eigen::Vector2d xy_i = Eigen::Vector2d::Zero(), xy_j = Eigen::Vector2d::Zero();
	double z_lo_mm = 0, z_hi_mm = 0, width_mm = 0;
};

/** Makes plane hypotheses for one model against scenes (PlaneHypotheses.h). */
class PlaneHypothesisGenerator
{
 public:
	/** @p model_O: the model's features (featuresOf); @p base_z_mm: modelBaseZ_mm. */
	PlaneHypothesisGenerator(std::vector<Feature> model_O, double base_z_mm,
	                         const PlaneHypothesisOptions& opts);

	/** All rim and line hypotheses of @p scene_S on @p plane. */
	std::vector<PlaneHypothesis> generate(const std::vector<Feature>& scene_S,
	                                      const SupportPlane& plane) const;

	/** Height (mm) of the model's base point (0, 0, base z) of @p T_OinS above @p plane. */
	double baseOffset_mm(const Eigen::Isometry3d& T_OinS, const SupportPlane& plane) const;

	const std::vector<size_t>& rims() const { return rims_; }
	const std::vector<size_t>& horizontalLines() const { return lines_; }
	const std::vector<LimbCylinder>& limbCylinders() const { return cylinders_; }
	/** Pairs of the model's vertical edges for edge-pair hypotheses (empty unless
	 * edge_pair_hypotheses and the model has no cylinder). */
	const std::vector<VerticalEdgePair>& verticalEdgePairs() const { return edge_pairs_; }
	double baseZ_mm() const { return base_z_mm_; }

 private:
	std::vector<Feature> model_;
	double base_z_mm_;
	PlaneHypothesisOptions opts_;
	std::vector<size_t> rims_;   ///< model conics near +z
	std::vector<size_t> lines_;  ///< model lines near horizontal and long enough
	std::vector<LimbCylinder> cylinders_;  ///< empty unless limb_hypotheses
	std::vector<VerticalEdgePair> edge_pairs_;

	void findVerticalEdgePairs();
	/** Edge-pair hypotheses for the vertical scene lines @p verticals (indices into @p scene). */
	void addEdgePairHypotheses(const std::vector<Feature>& scene,
	                           const std::vector<size_t>& verticals, const SupportPlane& plane,
	                           std::vector<PlaneHypothesis>& out) const;
	void findLimbCylinders();
	void addLimbHypotheses(const LimbCylinder& c, size_t s, const Feature& scene_line,
	                       const SupportPlane& plane, std::vector<PlaneHypothesis>& out) const;

	void addRimHypotheses(size_t rim, size_t s, const Feature& conic, const SupportPlane& plane,
	                      std::vector<PlaneHypothesis>& out) const;
	void addLineHypotheses(size_t line, size_t s, const Feature& scene_line,
	                       const SupportPlane& plane, std::vector<PlaneHypothesis>& out) const;
};

}  // namespace mrolr::recog
