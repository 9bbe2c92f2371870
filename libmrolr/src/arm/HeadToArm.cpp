#include <mrolr/arm/HeadToArm.h>
#include <mrolr/geometry/PoseUnits.h>

namespace mrolr::arm
{
Eigen::Isometry3d objectInHeadCentre(const geometry::BiSightHead& head,
                                     const geometry::HeadAngles& angles,
                                     const Eigen::Isometry3d& T_OinL_mm)
{
	return geometry::inMm(head.T_LinC0(angles)) * T_OinL_mm;
}

}  // namespace mrolr::arm
