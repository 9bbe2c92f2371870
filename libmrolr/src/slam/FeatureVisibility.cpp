#include <mrolr/geometry/IdealHead.h>
#include <mrolr/slam/FeatureVisibility.h>

#include <cmath>

namespace mrolr::slam
{
std::string toString(Visibility v)
{
	switch (v)
	{
		case Visibility::Visible:
			return "visible";
		case Visibility::AtHeadCentre:
			return "at head centre";
		case Visibility::BeyondPanLimit:
			return "beyond pan limit";
		case Visibility::BeyondTiltLimit:
			return "beyond tilt limit";
		case Visibility::BeyondVergenceLimit:
			return "beyond vergence limit";
		case Visibility::DistanceRatio:
			return "distance ratio";
		case Visibility::ViewDirection:
			return "view direction";
	}
	return "?";
}

Visibility headCanFixate(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                         const HeadModelOptions& head)
{
	const Eigen::Vector3d m = pointInHead(x_v, p_FinW, head.constants);
	if (!(std::hypot(m.x(), m.z()) > 1e-9)) return Visibility::AtHeadCentre;
	const Eigen::Vector3d h = geometry::idealHeadMeasure(m, head.constants.interocular_m);
	const double k = M_PI / 180;
	if (std::abs(h[0]) > head.pan_limit_deg * k) return Visibility::BeyondPanLimit;
	if (std::abs(h[1]) > head.tilt_limit_deg * k) return Visibility::BeyondTiltLimit;
	if (h[2] > head.vergence_limit_deg * k) return Visibility::BeyondVergenceLimit;
	return Visibility::Visible;
}

Visibility assessVisibility(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                            const Eigen::Vector3d& p_C0atInitInW, const SlamOptions& o)
{
	const Visibility limits = headCanFixate(x_v, p_FinW, o.head);
	if (limits != Visibility::Visible) return limits;
	const Eigen::Vector3d now = p_FinW - headCentreInW(x_v, o.head.constants);
	const Eigen::Vector3d then = p_FinW - p_C0atInitInW;
	if (!(then.norm() > 0)) return Visibility::AtHeadCentre;
	const double ratio = now.norm() / then.norm();
	if (ratio < o.visibility_ratio_min || ratio > o.visibility_ratio_max)
		return Visibility::DistanceRatio;
	const double cosang = now.dot(then) / (now.norm() * then.norm());
	if (std::acos(std::clamp(cosang, -1.0, 1.0)) > o.max_view_change_deg * M_PI / 180)
		return Visibility::ViewDirection;
	return Visibility::Visible;
}

}  // namespace mrolr::slam
