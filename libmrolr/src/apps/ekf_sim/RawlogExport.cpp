#include "SimulationOutputs.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <stdexcept>

namespace mrolr::apps::detail
{
namespace
{
/** Thesis (z, x, φ) → MRPT CPose2D(x forward, y left, φ). */
mrpt::poses::CPose2D toMrpt(const Eigen::Vector3d& p)
{
	return {p[0], p[1], p[2]};
}

mrpt::obs::CObservationBearingRange::TMeasurement toBearingRange(const Eigen::Vector3d& h,
                                                                 int32_t id,
                                                                 const eval::SimulationSetup& s)
{
	// Range from vergence: r = I / (2 tan γ), var_r = (dr/dγ)² σ_γ²; yaw = pan, pitch = −elevation.
	const double I = s.slam.head.constants.interocular_m, g = h[2];
	const double dr_dg = -I / (2 * std::sin(g) * std::sin(g));
	mrpt::obs::CObservationBearingRange::TMeasurement m;
	m.range = static_cast<float>(I / (2 * std::tan(g)));
	m.yaw = static_cast<float>(h[0]);
	m.pitch = static_cast<float>(-h[1]);
	m.landmarkID = id;
	m.covariance.setZero();
	m.covariance(0, 0) = dr_dg * dr_dg * s.slam.std_vergence_rad * s.slam.std_vergence_rad;
	m.covariance(1, 1) = s.slam.std_pan_rad * s.slam.std_pan_rad;
	m.covariance(2, 2) = s.slam.std_elevation_rad * s.slam.std_elevation_rad;
	return m;
}

int32_t landmarkId(const world::World& w, const std::string& name)
{
	for (size_t k = 0; k < w.landmarks.size(); ++k)
		if (w.landmarks[k].name == name) return static_cast<int32_t>(k);
	return -1;
}
}  // namespace

void writeRawlog(const std::string& path, const world::World& world, const eval::RunResult& run,
                 const eval::SimulationSetup& setup)
{
	mrpt::obs::CRawlog rawlog;
	auto t = mrpt::Clock::fromDouble(0.0);
	mrpt::poses::CPose2D last =
	    world.waypoints.empty()
	        ? mrpt::poses::CPose2D()
	        : toMrpt({world.waypoints[0].z_m, world.waypoints[0].x_m, world.waypoints[0].phi_rad});
	for (size_t k = 0; k < run.steps.size(); ++k)
	{
		t += std::chrono::microseconds(static_cast<long>(1e6 * run.controls_odometry[k][2]));
		const mrpt::poses::CPose2D now = toMrpt(run.steps[k].dead_reckoning);
		mrpt::obs::CActionRobotMovement2D move;
		move.computeFromOdometry(now - last,
		                         mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
		move.timestamp = t;
		last = now;
		mrpt::obs::CActionCollection acts;
		acts.insert(move);
		rawlog.insert(acts);
		auto obs = mrpt::obs::CObservationBearingRange::Create();
		obs->sensorLabel = "BISIGHT_IDEAL_HEAD";
		obs->timestamp = t;
		obs->sensorLocationOnRobot =
		    mrpt::poses::CPose3D(0, 0, setup.slam.head.constants.head_height_m, 0, 0, 0);
		obs->validCovariances = true;
		obs->fieldOfView_yaw = static_cast<float>(2 * setup.slam.head.pan_limit_deg * M_PI / 180);
		obs->fieldOfView_pitch =
		    static_cast<float>(2 * setup.slam.head.tilt_limit_deg * M_PI / 180);
		for (const auto& [label, h] : run.measurements[k])
			obs->sensedData.push_back(toBearingRange(h, landmarkId(world, label), setup));
		mrpt::obs::CSensoryFrame sf;
		sf.insert(obs);
		rawlog.insert(sf);
	}
	if (!rawlog.saveToRawLogFile(path))
		throw std::runtime_error("cannot write rawlog '" + path + "'");
}

}  // namespace mrolr::apps::detail
