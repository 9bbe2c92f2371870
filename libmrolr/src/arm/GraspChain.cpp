#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/GripperPose.h>
#include <mrolr/arm/PoseText.h>
#include <mrolr/util/Config.h>

#include <mrolr/util/OptionsBinder.h>

#include <Eigen/SVD>

#include <iomanip>
#include <ostream>
#include <stdexcept>

namespace mrolr::arm
{
void ArmMount::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                  const std::string& section)
{
	const std::string key = "T_C0inA";
	const auto v = util::readDoubles(cfg, section, key, 12);
	try
	{
		T_C0inA = poseFrom12(v, util::describeKey(cfg, section, key));
	}
	catch (const PoseInputError& e)
	{
		throw util::ConfigError(e.what());
	}
}

ArmMount ArmMount::fromFile(const std::string& path, const std::string& section)
{
	return util::loadOptionsFile<ArmMount>(path, section);
}

void ArmMount::dump(std::ostream& out) const
{
	out << std::setprecision(12) << "T_C0inA =";
	for (double x : poseTo12(T_C0inA)) out << " " << x;
	out << "\n";
}

Eigen::Isometry3d objectInArm(const Eigen::Isometry3d& T_C0inA, const Eigen::Isometry3d& T_OinC0)
{
	return T_C0inA * T_OinC0;
}

Eigen::Isometry3d calibrateHeadInArm(const Eigen::Isometry3d& T_OinA,
                                     const Eigen::Isometry3d& T_OinC0)
{
	return T_OinA * T_OinC0.inverse(Eigen::Isometry);
}

Eigen::Isometry3d calibrateHeadInArm(
    const std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>>& pairs)
{
	if (pairs.empty()) throw std::invalid_argument("calibrateHeadInArm: no test objects given");
	Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
	for (const auto& [A, C] : pairs) sum += A.linear() * C.linear().transpose();
	Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
	Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
	D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = svd.matrixU() * D * svd.matrixV().transpose();
	Eigen::Vector3d t = Eigen::Vector3d::Zero();
	for (const auto& [A, C] : pairs) t += A.translation() - T.linear() * C.translation();
	T.translation() = t / static_cast<double>(pairs.size());
	return T;
}

Eigen::Isometry3d graspInObject(const model::Grasp& grasp)
{
	return poseFromGripper({grasp.p_mm, grasp.yaw_deg, grasp.pitch_deg, grasp.roll_deg});
}

Eigen::Isometry3d graspInArm(const Eigen::Isometry3d& T_C0inA, const Eigen::Isometry3d& T_OinC0,
                             const model::Grasp& grasp)
{
	return objectInArm(T_C0inA, T_OinC0) * graspInObject(grasp);
}

}  // namespace mrolr::arm
