#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace mrolr::io
{
namespace fs = std::filesystem;

struct RawlogWriter::Impl
{
	mrpt::io::CFileGZOutputStream file;
};

std::string imagesDirFor(const std::string& rawlog_path)
{
	const fs::path p(rawlog_path);
	return (p.parent_path() / (p.stem().string() + "_Images")).string();
}

namespace
{
mrpt::poses::CPose3D poseOfMatrix(const Eigen::Isometry3d& T)
{
	mrpt::math::CMatrixDouble44 H;
	H.asEigen() = T.matrix();
	return mrpt::poses::CPose3D(H);
}

mrpt::img::CImage external(const mrpt::img::CImage& img, const std::string& dir,
                           const std::string& name)
{
	if (!img.saveToFile((fs::path(dir) / name).string()))
		throw std::runtime_error("cannot write image " + (fs::path(dir) / name).string());
	mrpt::img::CImage e;
	e.setExternalStorage(name);
	return e;
}

mrpt::obs::CObservationStereoImages::Ptr stereoObs(const RawlogRecord& r, const std::string& dir,
                                                   size_t index)
{
	auto o = mrpt::obs::CObservationStereoImages::Create();
	o->sensorLabel = "BISIGHT";
	o->timestamp = stampOf(r.time_s);
	char name[64];
	std::snprintf(name, sizeof(name), "BISIGHT_%06zu", index);
	o->imageLeft = external(r.left, dir, std::string(name) + "_left.png");
	o->imageRight = external(r.right, dir, std::string(name) + "_right.png");
	o->hasImageRight = true;
	o->leftCamera = o->rightCamera = r.camera;
	o->cameraPose = mrpt::poses::CPose3DQuat(poseOfMatrix(r.T_LcvInVehicle));
	o->rightCameraPose = mrpt::poses::CPose3DQuat(poseOfMatrix(r.T_RcvInLcv));
	return o;
}

mrpt::obs::CSensoryFrame frameOf(const RawlogRecord& r, const std::string& dir, size_t index)
{
	mrpt::obs::CSensoryFrame sf;
	auto odo = mrpt::obs::CObservationOdometry::Create();
	odo->sensorLabel = "ODOMETRY";
	odo->timestamp = stampOf(r.time_s);
	odo->odometry = geometry::vehicleToMrpt(r.odometry_zxphi);
	odo->hasEncodersInfo = true;
	odo->encoderRightTicks = int32_t(r.ticks_right);
	odo->encoderLeftTicks = int32_t(r.ticks_left);
	sf.insert(odo);
	auto head = mrpt::obs::CObservationRawDAQ::Create();
	head->sensorLabel = "HEAD_ANGLES";
	head->timestamp = stampOf(r.time_s);
	head->AIN_double = {r.head_rad[0], r.head_rad[1], r.head_rad[2], r.head_rad[3]};
	head->AIN_channel_count = 4;
	sf.insert(head);
	if (r.true_zxphi)
	{
		auto gt = mrpt::obs::CObservationRobotPose::Create();
		gt->sensorLabel = "GROUND_TRUTH";
		gt->timestamp = stampOf(r.time_s);
		gt->pose.mean = mrpt::poses::CPose3D(geometry::vehicleToMrpt(*r.true_zxphi));
		sf.insert(gt);
	}
	if (r.has_stereo) sf.insert(stereoObs(r, dir, index));
	return sf;
}
}  // namespace

RawlogWriter::RawlogWriter(const std::string& path)
    : impl_(std::make_unique<Impl>()), images_dir_(imagesDirFor(path))
{
	if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path());
	fs::create_directories(images_dir_);
	if (!impl_->file.open(path, 1))
		throw std::runtime_error("cannot open rawlog " + path + " for writing");
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const RawlogRecord& r)
{
	mrpt::obs::CActionCollection acts;
	mrpt::obs::CActionRobotMovement2D move;
	move.timestamp = stampOf(r.time_s);
	const auto delta = geometry::vehicleToMrpt(r.odometry_zxphi) -
	                   geometry::vehicleToMrpt(count_ == 0 ? r.odometry_zxphi : last_odometry_);
	move.computeFromOdometry(delta, mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
	acts.insert(move);
	auto out = mrpt::serialization::archiveFrom(impl_->file);
	out << acts << frameOf(r, images_dir_, count_);
	last_odometry_ = r.odometry_zxphi;
	++count_;
}

}  // namespace mrolr::io
