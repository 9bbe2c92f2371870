#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/GripperPose.h>
#include <mrolr/util/Config.h>

#include <mrpt/core/bits_math.h>

#include <cmath>

namespace mrolr::arm
{
namespace
{
Eigen::Matrix3d rotZ(double a)
{
	return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).matrix();
}
Eigen::Matrix3d rotY(double a)
{
	return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).matrix();
}
}  // namespace

Eigen::Matrix3d rotationFromYawPitchRoll(double yaw_deg, double pitch_deg, double roll_deg)
{
	using mrpt::DEG2RAD;
	return rotZ(DEG2RAD(yaw_deg)) * rotY(DEG2RAD(90.0 + pitch_deg)) *
	       rotZ(DEG2RAD(180.0 + roll_deg));
}

Eigen::Isometry3d poseFromGripper(const GripperPose& g)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = rotationFromYawPitchRoll(g.yaw_deg, g.pitch_deg, g.roll_deg);
	T.translation() = g.p_mm;
	return T;
}

GripperPose gripperFromPose(const Eigen::Isometry3d& T)
{
	const Eigen::Matrix3d R = T.linear();
	const Eigen::Vector3d a = R.col(2);
	const double horiz = std::hypot(a.x(), a.y());
	GripperPose g;
	g.p_mm = T.translation();
	g.pitch_deg = mrpt::RAD2DEG(std::atan2(-a.z(), horiz));
	g.yaw_deg = horiz > 1e-12 ? mrpt::RAD2DEG(std::atan2(a.y(), a.x())) : 0.0;
	// Roll: angle of x_G from the roll-0 axes of the same yaw and pitch.
	const Eigen::Matrix3d R0 = rotationFromYawPitchRoll(g.yaw_deg, g.pitch_deg, 0);
	const Eigen::Vector3d x = R.col(0);
	g.roll_deg = mrpt::RAD2DEG(std::atan2(x.dot(R0.col(1)), x.dot(R0.col(0))));
	return g;
}

GripperPose parseGripper(const std::string& text, const std::string& what)
{
	const auto fields = util::splitFields(text);
	std::vector<double> v;
	for (const auto& f : fields)
	{
		double d = 0;
		if (!util::parseDouble(f, d)) throw PoseInputError(what + ": '" + f + "' is not a number");
		v.push_back(d);
	}
	if (v.size() != 6)
		throw PoseInputError(what + ": expected 6 numbers x,y,z,yaw,pitch,roll, got '" + text +
		                     "'");
	GripperPose g;
	g.p_mm = {v[0], v[1], v[2]};
	g.yaw_deg = v[3];
	g.pitch_deg = v[4];
	g.roll_deg = v[5];
	return g;
}

}  // namespace mrolr::arm
