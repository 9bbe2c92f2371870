#pragma once
// Shared pieces of the mrolr-sim commands (private to app_sim).

#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/sim/GroundTruth.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/world/World.h>

#include <mrpt/img/CImage.h>
#include <mrpt/math/CMatrixF.h>

#include <nlohmann/json.hpp>

#include <string>

namespace mrolr::apps::simdetail
{
/** 4×4 row-major matrix as nested JSON arrays. */
nlohmann::json matrixJson(const Eigen::Isometry3d& T);

/** truth.json of one snapshot (docs/sim.md "truth.json"). */
nlohmann::json truthJson(const world::World& w, const geometry::BiSightHead& head,
                         const Eigen::Vector3d& xv, const geometry::HeadAngles& a,
                         const sim::StereoFrame& f);

/** Depth (m) as a 16-bit PNG in millimetres (0 = nothing rendered). */
void saveDepthPng(const mrpt::math::CMatrixFloat& depth_m, const std::string& path);

/** Left and right side by side with an 8-pixel white gap (for viewing). */
void savePair(const mrpt::img::CImage& left, const mrpt::img::CImage& right,
              const std::string& path);

/** Saves an image, throwing std::runtime_error naming the path on failure. */
void saveImage(const mrpt::img::CImage& img, const std::string& path);

/** Render options from [render] of @p sim_config_path if that file exists, else defaults. */
sim::RenderOptions renderOptions(const std::string& sim_config_path);

}  // namespace mrolr::apps::simdetail
