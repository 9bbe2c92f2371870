#pragma once
/** An upper bound on the verification score (Verification.h) that ANY pose of a model can reach in
 * a scene, computed without matching: it lets the fine-to-coarse search (thesis 6.4) skip the
 * levels that cannot possibly verify, so an absent model is cheap (beyond the thesis).
 *
 * Why it bounds: with the model carried into the scene by any T, a scene line supports a model line
 * only with the part of it that lies within beta of the model segment, hence within
 * rho = R + beta of the carried model centroid (R: the model's radius about its centroid); a
 * scene conic only when its centre is within rho. That ball touches a scene feature, so it lies
 * inside the ball of radius 2 rho + h/2 about one of the features' samples (every h = rho/2 along
 * the lines, and the conic centres). One
 * scene line gives at most the longest model line's length to one model feature, and supports at
 * most K model features at once, K being the largest number of model features of one kind that
 * pass within 2 beta of each other with directions within 2 theta. So the supported length is at
 * most min(L_kind, K · Σ min(scene length inside the ball, longest model feature)) per kind. */

#include <mrolr/recog/ModelTable.h>

#include <vector>

namespace mrolr::recog
{
class SupportBound
{
 public:
	/** For verification tolerances up to @p beta_mm and @p theta_rad. */
	SupportBound(const ModelTable& model, double beta_mm, double theta_rad);

	/** Bound (mm) on verifyPose(model, scene', T, beta, theta, min_len).supported_mm over every
	 * pose T, every beta and theta up to the constructor's, every min_len and every scene' that is
	 * a subset of @p scene (the score bound is this over the level's model length). */
	double supportBound_mm(const std::vector<Feature>& scene) const;

	/** The same bound for the poses that put model feature @p focus on scene feature @p s0, as a
	 * clique's focus match does (within @p match_beta_mm of it, s0 a fragment of it): the carried
	 * centroid is then within |c − m_focus| (+ half the focus line's length) + 2 match_beta of
	 * s0's midpoint, so one ball about s0 holds all the support. */
	double focusSupportBound_mm(const std::vector<Feature>& scene, size_t focus, const Feature& s0,
	                            double match_beta_mm) const;

	double radius_mm() const { return radius_mm_; }  ///< R: model radius about its centroid

 private:
	const ModelTable& model_;
	double beta_mm_ = 0;
	Eigen::Vector3d centroid_ = Eigen::Vector3d::Zero();
	double radius_mm_ = 0;
	double lines_mm_ = 0, conics_mm_ = 0;  ///< model length per kind
	double longest_line_mm_ = 0, longest_conic_mm_ = 0;
	int k_lines_ = 0, k_conics_ = 0;  ///< multiplicities K

	int multiplicity(FeatureKind kind, double beta_mm, double theta_rad) const;
	/** min(L_kind, K · Σ min(scene length inside the ball, longest)) summed over kinds (mm). */
	double inBall_mm(const std::vector<Feature>& scene, const Eigen::Vector3d& p, double r) const;
};

}  // namespace mrolr::recog
