#pragma once
/** Known features (thesis 5.6.2): landmarks whose position in W is given beforehand and enter the
 * map with zero covariance, each with the patch saved when it was acquired. Stored as
 * maps/<name>/known_features.ini plus one PNG per feature:
 *   [known_features]
 *   # id = X Y Z patch.png     (W: x left, y up, z forward, metres; PNG relative to this file)
 *   fire_sign = 1.0 1.6 5.99 known_patches/fire_sign.png
 * The [known_features] section of a mission plan (maps/<name>/plan.ini, written by mrolr-map) has
 * the same lines with three sigmas after the PNG; they are checked and read past here. */

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mrolr::vision
{
struct KnownFeature
{
	std::string id;
	Eigen::Vector3d p_FinW = Eigen::Vector3d::Zero();  ///< metres, W
	cv::Mat patch;                                     ///< CV_8UC1, odd square
};

/** Reads @p path; throws util::ConfigError naming file, section and key for a malformed line or a
 * patch PNG that is missing, unreadable or not an odd square. */
std::vector<KnownFeature> loadKnownFeatures(const std::string& path);

/** Writes @p path and the patches as <dir of path>/known_patches/<id>.png. Throws on I/O errors. */
void saveKnownFeatures(const std::string& path, const std::vector<KnownFeature>& features);

}  // namespace mrolr::vision
