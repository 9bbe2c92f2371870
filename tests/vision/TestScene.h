#pragma once
// Shared set-up of the vision tests: the configured BiSight head and a synthetic stereo head
// showing textured points.
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/vision/SyntheticStereoHead.h>
#include <mrolr/vision/VisionOptions.h>

#include <string>

namespace mrolr::vision::test
{
inline geometry::BiSightHead configuredHead()
{
	return geometry::BiSightHead(
	    geometry::BiSightOptions::fromFile(std::string(MROLR_SOURCE_DIR) + "/config/bisight.ini"));
}

inline VisionOptions configuredVision()
{
	return VisionOptions::fromFile(std::string(MROLR_SOURCE_DIR) + "/config/slam.ini");
}

/** One textured point per position, textures from seeds 100, 101, … */
inline std::vector<TexturedPoint> texturedPoints(const std::vector<Eigen::Vector3d>& ps)
{
	std::vector<TexturedPoint> out;
	for (size_t i = 0; i < ps.size(); ++i) out.push_back({ps[i], makeTexture(31, 100 + i)});
	return out;
}

}  // namespace mrolr::vision::test
