#pragma once
/** Whether a feature can be measured from a vehicle pose (thesis 5.2.1 and the head's joint
 * limits): the ideal-head angles must be inside the pan, tilt and vergence limits, and for a
 * feature first seen from head position c_0 the ratio |y − c| / |y − c_0| must lie in [0.7, 1.4]
 * and the viewing direction may have turned by at most max_view_change_deg, because a patch only
 * matches from viewpoints near the one it was saved from. */

#include <mrolr/slam/SlamOptions.h>

#include <Eigen/Core>

#include <string>

namespace mrolr::slam
{
enum class Visibility
{
	Visible,
	AtHeadCentre,         ///< the point coincides with C0 (no direction)
	BeyondPanLimit,       ///< |pan| > pan_limit_deg
	BeyondTiltLimit,      ///< |elevation| > tilt_limit_deg
	BeyondVergenceLimit,  ///< too near: vergence > vergence_limit_deg
	DistanceRatio,        ///< |y − c| / |y − c_0| outside [ratio_min, ratio_max]
	ViewDirection         ///< viewing direction turned more than max_view_change_deg
};

std::string toString(Visibility v);

/** Head joint limits only: for candidate features that have never been seen. */
Visibility headCanFixate(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                         const HeadModelOptions& head);

/** Head limits and the viewpoint rules of 5.2.1 for a feature first seen from @p p_C0atInitInW. */
Visibility assessVisibility(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                            const Eigen::Vector3d& p_C0atInitInW, const SlamOptions& options);

}  // namespace mrolr::slam
