// Frame chain of the BiSight head (thesis 4.2.2, eqs 4.10–4.23): rotations, camera poses and the
// point in camera coordinates.
#include <mrolr/geometry/BiSightHead.h>

#include <cmath>

namespace mrolr::geometry
{
namespace
{
// The pan matrix form of eq 4.14, shared by the vergence matrices 4.16–4.17.
Eigen::Matrix3d aboutY(double a)
{
	const double c = std::cos(a), s = std::sin(a);
	Eigen::Matrix3d R;
	R << c, 0, -s,  //
	    0, 1, 0,    //
	    s, 0, c;
	return R;
}

double sideSign(Side side)
{
	return side == Side::Left ? 1.0 : -1.0;
}

double vergence(Side side, const HeadAngles& a)
{
	return side == Side::Left ? a.verg_left : a.verg_right;
}
}  // namespace

Eigen::Matrix3d R_C1fromC0(double pan)
{
	return aboutY(pan);
}

Eigen::Matrix3d R_C2fromC1(double tilt)
{
	const double c = std::cos(tilt), s = std::sin(tilt);
	Eigen::Matrix3d R;
	R << 1, 0, 0,  //
	    0, c, -s,  //
	    0, s, c;
	return R;
}

Eigen::Matrix3d R_LfromC2(double vergence)
{
	return aboutY(vergence);
}

Eigen::Matrix3d R_thesisFromCv()
{
	return Eigen::Vector3d(-1, -1, 1).asDiagonal();
}

BiSightHead::BiSightHead(const BiSightOptions& options)
    : options_(options), camera_(options.camera())
{
}

Eigen::Isometry3d BiSightHead::T_CamInC0(Side side, const HeadAngles& angles) const
{
	// m_cam = R_γ (R_e (R_α m_G − p) − c) − n  ⇒  m_G = R_αᵀ (p + R_eᵀ (c + R_γᵀ (n + m_cam))).
	const Eigen::Matrix3d Ra = R_C1fromC0(angles.pan);
	const Eigen::Matrix3d Re = R_C2fromC1(angles.tilt);
	const Eigen::Matrix3d Rg = R_LfromC2(vergence(side, angles));
	const Eigen::Vector3d p(sideSign(side) * options_.interocular_m / 2, 0, options_.pan_offset_m);
	const Eigen::Vector3d c(0, options_.tilt_offset_m, 0);
	const Eigen::Vector3d n(0, 0, options_.optic_offset_m);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Rg * Re * Ra).transpose();
	T.translation() = Ra.transpose() * (p + Re.transpose() * (c + Rg.transpose() * n));
	return T;
}

Eigen::Isometry3d BiSightHead::T_LinC0(const HeadAngles& angles) const
{
	return T_CamInC0(Side::Left, angles);
}

Eigen::Vector3d BiSightHead::up_L(const HeadAngles& angles) const
{
	return T_LinC0(angles).linear().transpose() * Eigen::Vector3d::UnitY();
}

Eigen::Isometry3d BiSightHead::T_RinC0(const HeadAngles& angles) const
{
	return T_CamInC0(Side::Right, angles);
}

Eigen::Isometry3d BiSightHead::T_CamCvInC0(Side side, const HeadAngles& angles) const
{
	Eigen::Isometry3d T = T_CamInC0(side, angles);
	T.linear() = T.linear() * R_thesisFromCv();
	return T;
}

Eigen::Vector3d BiSightHead::pointInCamera(Side side, const Eigen::Vector3d& p_GinC0,
                                           const HeadAngles& angles) const
{
	return T_CamInC0(side, angles).inverse(Eigen::Isometry) * p_GinC0;
}

}  // namespace mrolr::geometry
