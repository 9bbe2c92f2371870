#include <mrolr/arm/HeadToArm.h>

namespace mrolr::arm
{
Eigen::Isometry3d objectInHeadCentre(const geometry::BiSightHead& head,
                                     const geometry::HeadAngles& angles,
                                     const Eigen::Isometry3d& T_OinL_mm)
{
	Eigen::Isometry3d T_LinC0 = head.T_LinC0(angles);
	T_LinC0.translation() *= 1000.0;  // m → mm
	return T_LinC0 * T_OinL_mm;
}

}  // namespace mrolr::arm
