#pragma once
/** Clustering of clique transforms (thesis 6.3.2: "cliques that produce near identical transforms
 * are considered as belonging to the same object; the mean transform is returned"). */

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace mrolr::recog
{
/** One clique's pose hypothesis T_OinS with a weight (its number of matched features). */
struct PoseHypothesis
{
	Eigen::Isometry3d T_OinS = Eigen::Isometry3d::Identity();
	double weight = 1;
};

/** Hypotheses that agree: their weighted mean pose and its spread. */
struct PoseCluster
{
	Eigen::Isometry3d mean = Eigen::Isometry3d::Identity();
	std::vector<size_t> members;  ///< indices into the hypotheses
	double weight = 0;            ///< summed weights
	double spread_rot_deg = 0;    ///< RMS rotation of the members from the mean (deg)
	double spread_trans_mm =
	    0;  ///< RMS distance of the carried model centroid from the mean's (mm)
};

/** Angle of the rotation R_a^T R_b (deg). */
double rotationDistanceDeg(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb);

/** Weighted mean of rotations: the principal eigenvector of sum w q q^T (sign-free quaternion
 * average) — and of translations. */
Eigen::Isometry3d meanTransform(const std::vector<Eigen::Isometry3d>& Ts,
                                const std::vector<double>& w);

/** Greedy clustering, heaviest hypothesis first: a hypothesis joins the first cluster whose seed
 * is within @p max_rotation_deg and moves @p centroid_O (model frame, mm) to within
 * @p max_translation_mm of where the seed moves it. Clusters are returned heaviest first, at most
 * @p max_clusters of them: the mean and spread of the lighter ones are not worked out. */
std::vector<PoseCluster> clusterTransforms(const std::vector<PoseHypothesis>& hyps,
                                           const Eigen::Vector3d& centroid_O,
                                           double max_rotation_deg, double max_translation_mm,
                                           size_t max_clusters = SIZE_MAX);

}  // namespace mrolr::recog
