// The robot's own arm in its cameras' view.
#include <mrolr/mission/SelfModel.h>

namespace mrolr::mission
{
SelfModel::SelfModel(const arm::RtxOptions& rtx, const arm::GraspFeasibilityOptions& grip,
                     const arm::MarkerOptions& marker, const Eigen::Isometry3d& T_C0inA_mm,
                     const geometry::BiSightHead& head)
    : body_(arm::rtxBody(rtx, grip, marker)), kin_(rtx), T_AinC0_mm_(T_C0inA_mm.inverse())
{
	const geometry::HeadAngles zero;
	cameras_mm_ = {head.T_LinC0(zero).translation() * 1000.0,
	               head.T_RinC0(zero).translation() * 1000.0};
	setJoints(arm::RtxJoints().toMmDeg());
}

void SelfModel::setJoints(const hw::ArmJoints& j)
{
	boxes_ = arm::placeBody(body_, kin_, arm::RtxJoints::fromMmDeg(j), T_AinC0_mm_);
}

bool SelfModel::isSelf(const Eigen::Vector3d& p_inC0_m) const
{
	return docked_ && hidden(boxes_, p_inC0_m);
}

bool SelfModel::isOnArm(const Eigen::Vector3d& p_inC0_m) const
{
	if (!docked_) return false;
	const Eigen::Vector3d p = p_inC0_m * 1000.0;
	for (const auto& box : boxes_)
		if (arm::segmentMeetsBox(p, p, box, kSelfMargin_mm)) return true;
	return false;
}

bool SelfModel::isSelfAt(const hw::ArmJoints& j, const Eigen::Vector3d& p_inC0_m) const
{
	return hidden(arm::placeBody(body_, kin_, arm::RtxJoints::fromMmDeg(j), T_AinC0_mm_), p_inC0_m);
}

bool SelfModel::hidden(const std::vector<arm::PlacedBox>& boxes,
                       const Eigen::Vector3d& p_inC0_m) const
{
	const Eigen::Vector3d p = p_inC0_m * 1000.0;
	for (const auto& box : boxes)
		for (const auto& c : cameras_mm_)
			if (arm::segmentMeetsBox(c, p, box, kSelfMargin_mm)) return true;
	return false;
}

}  // namespace mrolr::mission
