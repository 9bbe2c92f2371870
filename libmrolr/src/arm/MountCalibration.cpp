// The head-to-arm transform from marker positions (eq 6.7.2 over several poses).
#include <mrolr/arm/MountCalibration.h>
#include <mrolr/util/OptionsBinder.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <ostream>
#include <stdexcept>

namespace mrolr::arm
{
namespace
{
Eigen::Matrix3Xd columns(const std::vector<Eigen::Vector3d>& p)
{
	Eigen::Matrix3Xd m(3, p.size());
	for (size_t k = 0; k < p.size(); ++k) m.col(k) = p[k];
	return m;
}

/** The second singular value of the centred points, mm: zero when they lie on one line. */
double spreadOffLine(const Eigen::Matrix3Xd& p)
{
	const Eigen::Matrix3Xd centred = p.colwise() - p.rowwise().mean();
	return Eigen::JacobiSVD<Eigen::Matrix3Xd>(centred).singularValues()[1] /
	       std::sqrt(static_cast<double>(p.cols()));
}
}  // namespace

namespace
{
using O = MarkerOptions;

const util::OptionsBinder<O>& markerOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .vector3("p_MinG_mm", &O::p_MinG_mm, -1e4, 1e4)
	    .number("side_mm", &O::side_mm, 5, 500)
	    .integer("aruco_id", &O::aruco_id, 0, 49);
	return b;
}
}  // namespace

void MarkerOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	markerOptionsBinder().load(cfg, section, *this);
}

void MarkerOptions::dump(std::ostream& out) const
{
	markerOptionsBinder().dump(out, *this);
}

MountFit fitHeadInArm(const std::vector<Eigen::Vector3d>& p_MinA_mm,
                      const std::vector<Eigen::Vector3d>& p_MinC0_mm)
{
	if (p_MinA_mm.size() != p_MinC0_mm.size())
		throw std::invalid_argument("fitHeadInArm: " + std::to_string(p_MinA_mm.size()) +
		                            " arm points against " + std::to_string(p_MinC0_mm.size()) +
		                            " head points");
	if (p_MinA_mm.size() < 3)
		throw std::invalid_argument("fitHeadInArm: " + std::to_string(p_MinA_mm.size()) +
		                            " marker positions; at least 3 not on one line are needed");
	const Eigen::Matrix3Xd a = columns(p_MinA_mm), c = columns(p_MinC0_mm);
	if (spreadOffLine(c) < 1.0)
		throw std::invalid_argument(
		    "fitHeadInArm: the marker positions lie on one line (within 1 mm); the rotation about "
		    "it is unobservable");
	MountFit fit;
	fit.T_C0inA.matrix() = Eigen::umeyama(c, a, false);
	fit.points = p_MinA_mm.size();
	double sum2 = 0;
	for (size_t k = 0; k < fit.points; ++k)
	{
		const double e = (a.col(k) - fit.T_C0inA * c.col(k)).norm();
		sum2 += e * e, fit.max_mm = std::max(fit.max_mm, e);
	}
	fit.rms_mm = std::sqrt(sum2 / static_cast<double>(fit.points));
	return fit;
}

}  // namespace mrolr::arm
