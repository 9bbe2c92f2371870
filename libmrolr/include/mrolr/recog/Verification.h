#pragma once
/** Verification of a pose hypothesis (thesis 6.3.2 step 4, "transform the model into the scene"):
 * the whole model is carried into the scene by T_OinS and every model feature looks for scene
 * features that lie on it; the score is the supported fraction of the model's total length. */

#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/PoseEstimation.h>
#include <mrolr/recog/SelfOcclusion.h>

#include <Eigen/Geometry>

#include <vector>

namespace mrolr::recog
{
struct VerificationResult
{
	double score = 0;  ///< supported length / length of the model features considered, [0, 1]
	double considered_mm = 0;  ///< model length considered (all, or expected visible) (mm)
	double supported_mm = 0;   ///< supported model length (mm)
	double coverage = 0;  ///< supported length / length of the model features that have support
	int matched = 0;      ///< model features with at least a quarter of their length supported
	std::vector<Correspondence> correspondences;  ///< model feature (model frame) ↔ best support
};

/** Ranking of verified poses: the score, ties broken towards the pose whose supported features
 * are covered more completely (a fragment explained as a whole feature rather than as part of a
 * longer one). */
inline double rankOf(const VerificationResult& v)
{
	return v.score + 0.05 * v.coverage;
}

/** A scene line supports a transformed model line when it is within @p theta_rad of its direction
 * and both its endpoints are within @p beta_mm of the model line; the support is the overlap of
 * its projection with the model segment (summed, at most the model length). A scene conic supports
 * a model conic with centre within beta, normal within theta and semi-axes within beta + 5 %; the
 * support is the smaller arc length. Model features shorter than @p min_len_mm (which the scene
 * could not show, having been filtered by the same threshold) count neither way. With
 * @p occlusion (built on model.features(), camera at the scene frame's origin), each model feature
 * counts in the score's denominator only by its fraction not hidden by the object itself, and the
 * score is capped at 1. */
VerificationResult verifyPose(const ModelTable& model, const std::vector<Feature>& scene,
                              const Eigen::Isometry3d& T_OinS, double beta_mm, double theta_rad,
                              double min_len_mm = 0, const SelfOcclusion* occlusion = nullptr);

}  // namespace mrolr::recog
