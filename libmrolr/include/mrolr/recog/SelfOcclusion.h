#pragma once
/** Self-occlusion of a wire-frame model seen from a camera (beyond the thesis, used by
 * verification): from one viewpoint only the front of an object can be seen, so a pose is judged
 * by the support of the model length that is expected visible, not of the whole model. The
 * object's solid is approximated by a discrete-orientation polytope (k-DOP: the intersection of
 * the half-spaces n·x <= max_i n·p_i over fixed directions n) that encloses the convex hull of
 * points sampled on the model's features; a sample is hidden when the segment from the camera to
 * it passes through that polytope shrunk by a margin. Model frame, millimetres. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/Limbs.h>

#include <Eigen/Core>

#include <vector>

namespace mrolr::recog
{
class SelfOcclusion
{
 public:
	/** @p features_O model features (model frame, mm); @p margin_mm how far inside the enclosing
	 * polytope a sight line must pass to hide a sample (covers the polytope's excess over the
	 * hull and edges on the surface); @p directions number of polytope face directions. */
	explicit SelfOcclusion(const std::vector<Feature>& features_O, double margin_mm = 3,
	                       int directions = 100);

	/** Fraction in [0, 1] of each feature's samples (same order as the constructor's features)
	 * that a camera at @p c_O (model frame, mm) sees, judging by the object's own solid. */
	std::vector<double> visibleFractions(const Eigen::Vector3d& c_O) const;

	/** True when the segment from @p c_O to @p p_O crosses the shrunk polytope. */
	bool hidden(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** True when @p p_O is inside the shrunk polytope (inside the object's solid). */
	bool contains(const Eigen::Vector3d& p_O) const;

	/** As hidden(), but a point on the surface of one of the model's bodies of revolution (within
	 * the margin) is judged against those bodies' solids exactly (crossesSolid, shrunk by the
	 * margin): the polytope, convex, fills a bottle's neck and hides the ring where neck and
	 * shoulder meet, which the camera sees. Other points: hidden(). Used by the verification in
	 * the images; the 3D verification keeps hidden(). */
	bool hiddenOnBodies(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** True when the segment from @p c_O to a limb point @p p_O crosses the polytope of the
	 * features off the bodies' surfaces (a cup's handle in front of its side); never for a model
	 * that is all bodies. (The whole polytope cannot judge a limb: the sight ray grazes the body
	 * there, and the polytope does not follow its round surface.) */
	bool hiddenLimb(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** The model's bodies of revolution (revolutionBodiesOf the constructor's features), whose
	 * limbs the verification in the images adds at each pose (Limbs.h); the 3D verification
	 * does not use them. */
	const std::vector<RevolutionBody>& revolutionBodies() const { return bodies_; }

 private:
	std::vector<double> offsetsOf(const std::vector<std::vector<Eigen::Vector3d>>& pts,
	                              double margin_mm) const;
	bool crossesPolytope(const std::vector<double>& offsets, const Eigen::Vector3d& c_O,
	                     const Eigen::Vector3d& p_O) const;

	std::vector<Eigen::Vector3d> normals_;
	std::vector<double> offsets_;  ///< plane offsets, already shrunk by the margin
	std::vector<std::vector<Eigen::Vector3d>> samples_;  ///< per feature
	std::vector<RevolutionBody> bodies_;
	std::vector<double> rest_offsets_;  ///< polytope of the features off the bodies (may be empty)
	double margin_mm_;
};

/** Points along a feature: a line's samples from end to end, a conic's around its rim (an ellipse
 * as a circle of the mean semi-axis: the feature keeps no major-axis direction). */
std::vector<Eigen::Vector3d> samplesOf(const Feature& f, int count);

/** @p n nearly uniform unit directions (a Fibonacci sphere). */
std::vector<Eigen::Vector3d> sphereDirections(int n);

}  // namespace mrolr::recog
