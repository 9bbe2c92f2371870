#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/PoseText.h>
#include <mrolr/util/Config.h>

#include <Eigen/SVD>

#include <sstream>

namespace mrolr::arm
{
namespace
{
Eigen::Matrix3d nearestRotation(const Eigen::Matrix3d& M)
{
	Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
	return svd.matrixU() * svd.matrixV().transpose();
}

void requireRotation(const Eigen::Matrix3d& R, const std::string& what, double tolerance)
{
	const double orth = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
	const double det = R.determinant();
	if (orth <= tolerance && std::abs(det - 1.0) <= 3 * tolerance) return;
	std::ostringstream s;
	s << what << ": the 3x3 part is not a rotation (|R^T R - I| = " << orth << ", det = " << det
	  << "; tolerance " << tolerance << ")";
	throw PoseInputError(s.str());
}
}  // namespace

Eigen::Isometry3d poseFrom12(const std::vector<double>& v, const std::string& what,
                             double tolerance)
{
	if (v.size() != 12)
		throw PoseInputError(what + ": expected 12 numbers (rows of [R | t]), got " +
		                     std::to_string(v.size()));
	Eigen::Matrix3d R;
	Eigen::Vector3d t;
	for (int r = 0; r < 3; ++r)
	{
		for (int c = 0; c < 3; ++c) R(r, c) = v[static_cast<size_t>(4 * r + c)];
		t[r] = v[static_cast<size_t>(4 * r + 3)];
	}
	requireRotation(R, what, tolerance);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = nearestRotation(R);
	T.translation() = t;
	return T;
}

Eigen::Isometry3d parsePose12(const std::string& text, const std::string& what)
{
	std::vector<double> v;
	for (const auto& f : util::splitFields(text))
	{
		double d = 0;
		if (!util::parseDouble(f, d)) throw PoseInputError(what + ": '" + f + "' is not a number");
		v.push_back(d);
	}
	return poseFrom12(v, what);
}

std::vector<double> poseTo12(const Eigen::Isometry3d& T)
{
	std::vector<double> v;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) v.push_back(T.matrix()(r, c));
	return v;
}

}  // namespace mrolr::arm
