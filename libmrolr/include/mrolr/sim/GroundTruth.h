#pragma once
/** Ground truth of one rendered stereo pair: where every landmark and object really is, in the
 * frames the vision code estimates (left camera L, head centre C0; thesis axes, metres). */

#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/world/World.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace mrolr::sim
{
/** One landmark as seen in a pair. Pixels follow the head model (eq 4.24); `visible` means in both
 * images, in front of both cameras and not hidden (rendered depth agrees with its depth). */
struct LandmarkView
{
	std::string name;
	bool known = false;
	Eigen::Vector3d p_LinW = Eigen::Vector3d::Zero();
	Eigen::Vector3d p_LinC0 = Eigen::Vector3d::Zero();
	double uL = 0, vL = 0, uR = 0, vR = 0;
	bool visible = false;
};

/** One object as seen in a pair: its model frame O in L and C0 (metres), and the pixel of O's
 * origin in the left image; `visible` when that pixel is inside the left image. */
struct ObjectView
{
	std::string name, model;
	Eigen::Isometry3d T_OinL = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d T_OinC0 = Eigen::Isometry3d::Identity();
	double uL = 0, vL = 0;
	bool visible = false;
};

/** Views of every landmark of @p w for the head at @p T_C0inW with @p angles; @p frame supplies
 * the left depth image for the occlusion test (pass nullptr to skip it). */
std::vector<LandmarkView> landmarkViews(const world::World& w, const geometry::BiSightHead& head,
                                        const Eigen::Isometry3d& T_C0inW,
                                        const geometry::HeadAngles& angles,
                                        const StereoFrame* frame);

/** Views of every placed object of @p w. */
std::vector<ObjectView> objectViews(const world::World& w, const geometry::BiSightHead& head,
                                    const Eigen::Isometry3d& T_C0inW,
                                    const geometry::HeadAngles& angles);

}  // namespace mrolr::sim
