#include <mrolr/geometry/Frames.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace mrolr::geometry
{
namespace
{
mrpt::poses::CPose3D makePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
	mrpt::math::CMatrixDouble33 Rm;
	Rm.asEigen() = R;
	return mrpt::poses::CPose3D(Rm, mrpt::math::CVectorFixedDouble<3>(t));
}

Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = pose.getRotationMatrix().asEigen();
	T.translation() = Eigen::Vector3d(pose.x(), pose.y(), pose.z());
	return T;
}
}  // namespace

Eigen::Matrix3d R_mrptFromThesis()
{
	Eigen::Matrix3d P;
	P << 0, 0, 1,  //
	    1, 0, 0,   //
	    0, 1, 0;
	return P;
}

mrpt::math::TPoint3D pointToMrpt(const Eigen::Vector3d& p)
{
	return {p.z(), p.x(), p.y()};
}

Eigen::Vector3d pointFromMrpt(const mrpt::math::TPoint3D& p)
{
	return {p.y, p.z, p.x};
}

mrpt::poses::CPose3D poseToMrpt(const Eigen::Isometry3d& T)
{
	const Eigen::Matrix3d P = R_mrptFromThesis();
	return makePose(P * T.linear() * P.transpose(), P * T.translation());
}

Eigen::Isometry3d poseFromMrpt(const mrpt::poses::CPose3D& pose)
{
	const Eigen::Matrix3d P = R_mrptFromThesis();
	Eigen::Isometry3d T = toIsometry(pose);
	T.linear() = P.transpose() * T.linear() * P;
	T.translation() = P.transpose() * T.translation();
	return T;
}

mrpt::poses::CPose3D cameraPoseToMrpt(const Eigen::Isometry3d& T)
{
	const Eigen::Matrix3d P = R_mrptFromThesis();
	return makePose(P * T.linear(), P * T.translation());
}

Eigen::Isometry3d cameraPoseFromMrpt(const mrpt::poses::CPose3D& pose)
{
	const Eigen::Matrix3d P = R_mrptFromThesis();
	Eigen::Isometry3d T = toIsometry(pose);
	T.linear() = P.transpose() * T.linear();
	T.translation() = P.transpose() * T.translation();
	return T;
}

mrpt::poses::CPose2D vehicleToMrpt(const Eigen::Vector3d& xv)
{
	return mrpt::poses::CPose2D(xv[0], xv[1], xv[2]);
}

Eigen::Vector3d vehicleFromMrpt(const mrpt::poses::CPose2D& pose)
{
	return {pose.x(), pose.y(), mrpt::math::wrapToPi(pose.phi())};
}

Eigen::Isometry3d T_C0inW(const Eigen::Vector3d& xv, double head_height_m)
{
	// Heading φ turns the forward axis z towards x: R = R_C1fromC0(φ)ᵀ (rotation about y).
	const double c = std::cos(xv[2]), s = std::sin(xv[2]);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << c, 0, s,  //
	    0, 1, 0,            //
	    -s, 0, c;
	T.translation() = Eigen::Vector3d(xv[1], head_height_m, xv[0]);
	return T;
}

}  // namespace mrolr::geometry
