// TUM trajectory files (TumTrajectory.h), through MRPT's poses and quaternions.
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/TumTrajectory.h>

#include <mrpt/math/CQuaternion.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mrolr::io
{
namespace
{
constexpr double kPlanarTolerance = 1e-6;  // m of height, and of quaternion x, y: rounding only
}

std::string tumLine(const StampedVehicle& s)
{
	const mrpt::poses::CPose3DQuat q(mrpt::poses::CPose3D(geometry::vehicleToMrpt(s.xv_zxphi)));
	std::ostringstream out;
	out << std::setprecision(9) << std::fixed << s.time_s << std::defaultfloat
	    << std::setprecision(12) << " " << q.x() << " " << q.y() << " " << q.z() << " "
	    << q.quat().x() << " " << q.quat().y() << " " << q.quat().z() << " " << q.quat().r();
	return out.str();
}

void writeTum(const std::string& path, const std::vector<StampedVehicle>& poses)
{
	for (size_t i = 0; i < poses.size(); ++i)
	{
		if (!std::isfinite(poses[i].time_s) || !poses[i].xv_zxphi.allFinite())
			throw std::invalid_argument(path + ": pose " + std::to_string(i) +
			                            " is not finite");
		if (i > 0 && poses[i].time_s < poses[i - 1].time_s)
			throw std::invalid_argument(path + ": pose " + std::to_string(i) + " at " +
			                            std::to_string(poses[i].time_s) + " s goes back in time");
	}
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
	f << "# timestamp tx ty tz qx qy qz qw (MRPT axes: x forward, z up; MROLR x_v (z, x, phi))\n";
	for (const auto& p : poses) f << tumLine(p) << "\n";
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
}

std::vector<StampedVehicle> readTum(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error("cannot read '" + path + "'");
	std::vector<StampedVehicle> out;
	std::string line;
	for (int n = 1; std::getline(f, line); ++n)
	{
		if (line.empty() || line[0] == '#') continue;
		std::istringstream in(line);
		double v[8];
		std::string rest;
		for (double& x : v)
			if (!(in >> x)) throw std::runtime_error(path + ":" + std::to_string(n) +
			                                         ": expected 8 numbers, got '" + line + "'");
		if (in >> rest)
			throw std::runtime_error(path + ":" + std::to_string(n) + ": trailing '" + rest + "'");
		const double norm = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
		if (!(std::abs(norm - 1) < 1e-3))
			throw std::runtime_error(path + ":" + std::to_string(n) +
			                         ": the quaternion is not a unit one (norm " +
			                         std::to_string(norm) + ")");
		const mrpt::math::CQuaternionDouble q(v[7] / norm, v[4] / norm, v[5] / norm, v[6] / norm);
		if (std::abs(v[3]) > kPlanarTolerance || std::abs(q.x()) > kPlanarTolerance ||
		    std::abs(q.y()) > kPlanarTolerance)
			throw std::runtime_error(path + ":" + std::to_string(n) +
			                         ": not a planar pose (z or tilt is not 0)");
		const mrpt::poses::CPose3D pose(mrpt::poses::CPose3DQuat(v[1], v[2], v[3], q));
		out.push_back({v[0], geometry::vehicleFromMrpt(mrpt::poses::CPose2D(pose))});
	}
	return out;
}

}  // namespace mrolr::io
