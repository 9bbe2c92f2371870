#pragma once
/** Pose of a model in a scene from matched features: the Faugeras–Hebert least-squares method
 * (thesis 6.3.2 citing [FHPP84]) and a point-based estimate with OpenGV's Arun method. Both return
 * T_OinS, the rigid transform taking model coordinates (frame O) into the scene's frame (mm). */

#include <mrolr/recog/Feature.h>

#include <Eigen/Geometry>

#include <optional>
#include <utility>
#include <vector>

namespace mrolr::recog
{
/** A model feature and the scene feature it matches, the scene feature oriented so that its
 * direction/normal agrees with the model's. */
struct Correspondence
{
	Feature model;
	Feature scene;
};

/** Rotation R minimising sum w |R a_i - b_i|^2 as the unit quaternion of Horn/Faugeras–Hebert: the
 * eigenvector of the largest eigenvalue of the 4×4 matrix built from sum w a b^T. Returns nullopt
 * when the directions do not fix the rotation (all parallel). */
std::optional<Eigen::Matrix3d> rotationFromDirections(const std::vector<Eigen::Vector3d>& a,
                                                      const std::vector<Eigen::Vector3d>& b,
                                                      const std::vector<double>& w);

/** Faugeras–Hebert pose: rotation from matched line directions, conic normals and the directions
 * between matched conic centres; translation t minimising sum |P_i (R m_i + t - m'_i)|^2 over lines
 * (P_i projects perpendicular to the scene line, so fragments constrain it exactly) plus
 * sum |R c_i + t - c'_i|^2 over conic centres. nullopt when rotation or translation is
 * undetermined. */
std::optional<Eigen::Isometry3d> faugerasHebertPose(const std::vector<Correspondence>& cs);

/** Points that correspond regardless of fragmentation: conic centres, for each pair of matched
 * lines at least 30° apart the midpoint of their common perpendicular, and for each line–conic pair
 * the foot of the perpendicular from the centre onto the line. first = model, second = scene. */
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> correspondingPoints(
    const std::vector<Correspondence>& cs);

/** OpenGV point-cloud alignment of correspondingPoints(cs): opengv::point_cloud::threept_arun on
 * all points, or inside opengv::sac::Ransac (threshold @p ransac_threshold_mm, fixed seed) when
 * there are at least 6 points. nullopt with fewer than 3 points or when they are (nearly)
 * collinear. */
std::optional<Eigen::Isometry3d> arunPose(const std::vector<Correspondence>& cs,
                                          double ransac_threshold_mm);

}  // namespace mrolr::recog
