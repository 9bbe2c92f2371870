// An observations-only rawlog (a mission's recording, ObservationLog.h) as RawlogRecords: one
// record per odometry reading and one per stereo pair, as RawlogWriter's recordings have them.
#include "RawlogFromObservations.h"

#include <mrolr/geometry/Frames.h>

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationStereoImages.h>

namespace mrolr::io
{
namespace
{
Eigen::Isometry3d isometryOf(const mrpt::poses::CPose3DQuat& q)
{
	Eigen::Isometry3d T;
	T.matrix() =
	    mrpt::poses::CPose3D(q).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
	return T;
}

/** The state the records carry forward: the latest odometry, head angles and truth (the base
 * stands still between its steps, so a pair's truth is its step's). */
struct Latest
{
	RawlogRecord state;
	mrpt::obs::CObservationStereoImages::Ptr pair;
};

void readOdometry(const mrpt::obs::CObservationOdometry& o, Latest& l, std::vector<RawlogRecord>& out)
{
	l.state.time_s = timeOf(o.timestamp);
	l.state.odometry_zxphi = geometry::vehicleFromMrpt(o.odometry);
	l.state.ticks_right = o.encoderRightTicks, l.state.ticks_left = o.encoderLeftTicks;
	out.push_back(l.state);
}

/** The estimate after a step, on that step's odometry record (the last one before it). */
void readEstimate(const mrpt::obs::CObservationRobotPose& e, std::vector<RawlogRecord>& out)
{
	for (auto it = out.rbegin(); it != out.rend(); ++it)
		if (!it->has_stereo)
		{
			it->estimate_zxphi = geometry::vehicleFromMrpt(mrpt::poses::CPose2D(e.pose.mean));
			const int at[3] = {0, 1, 3};  // (x, y, yaw) of (x, y, z, yaw, pitch, roll)
			for (int i = 0; i < 3; ++i)
				for (int k = 0; k < 3; ++k) it->estimate_P(i, k) = e.pose.cov(at[i], at[k]);
			return;
		}
}

void readGrab(const mrpt::obs::CObservationRawDAQ& grab, Latest& l, const std::string& path,
              ImageLoading images, std::vector<RawlogRecord>& out)
{
	if (!l.pair || grab.AIN_double.size() < 4) return;  // a failed grab: no pair
	RawlogRecord r = l.state;
	r.time_s = timeOf(grab.timestamp);
	r.head_rad = Eigen::Vector4d(grab.AIN_double.data());
	r.has_stereo = true;
	r.left_file = externalFile(l.pair->imageLeft, path);
	r.right_file = externalFile(l.pair->imageRight, path);
	if (images == ImageLoading::Load)
		r.left = loadExternal(l.pair->imageLeft, path), r.right = loadExternal(l.pair->imageRight, path);
	r.camera = l.pair->leftCamera;
	r.T_LcvInVehicle = isometryOf(l.pair->cameraPose);
	r.T_RcvInLcv = isometryOf(l.pair->rightCameraPose);
	out.push_back(std::move(r));
	l.pair.reset();
}
}  // namespace

std::vector<RawlogRecord> recordsOf(const ObservationLog& log, const std::string& path,
                                    ImageLoading images)
{
	std::vector<RawlogRecord> out;
	Latest l;
	for (const auto& obs : log.observations)
	{
		if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
			readOdometry(*o, l, out);
		else if (const auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(obs))
			l.pair = s;
		else if (const auto g = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obs);
		         g && g->sensorLabel == "GROUND_TRUTH")
			l.state.true_zxphi = geometry::vehicleFromMrpt(mrpt::poses::CPose2D(g->pose.mean));
		else if (g && g->sensorLabel == "ESTIMATE")
			readEstimate(*g, out);
		else if (const auto d = std::dynamic_pointer_cast<mrpt::obs::CObservationRawDAQ>(obs))
		{
			if (d->sensorLabel == "HEAD_ANGLES" && d->AIN_double.size() == 4)
				l.state.head_rad = Eigen::Vector4d(d->AIN_double.data());
			if (d->sensorLabel == "HEAD_GRAB") readGrab(*d, l, path, images, out);
		}
	}
	return out;
}

}  // namespace mrolr::io
