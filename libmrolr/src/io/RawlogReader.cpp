#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>
#include "RawlogFromObservations.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <stdexcept>

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

mrpt::img::CImage loaded(const mrpt::img::CImage& external)
{
	const std::string file = external.getExternalStorageFileAbsolutePath();
	mrpt::img::CImage img;
	if (!img.loadFromFile(file)) throw std::runtime_error("cannot read external image " + file);
	return img;
}

void readStereo(const mrpt::obs::CObservationStereoImages& s, RawlogRecord& r, ImageLoading images)
{
	r.has_stereo = true;
	r.left_file = s.imageLeft.getExternalStorageFileAbsolutePath();
	r.right_file = s.imageRight.getExternalStorageFileAbsolutePath();
	if (images == ImageLoading::Load) r.left = loaded(s.imageLeft), r.right = loaded(s.imageRight);
	r.camera = s.leftCamera;
	r.T_LcvInVehicle = isometryOf(s.cameraPose);
	r.T_RcvInLcv = isometryOf(s.rightCameraPose);
}

[[noreturn]] void fail(const std::string& path, size_t i, const std::string& why)
{
	throw std::runtime_error(path + ": record " + std::to_string(i) + ": " + why);
}

RawlogRecord recordOf(const mrpt::obs::CSensoryFrame& sf, const std::string& path, size_t i,
                      ImageLoading images)
{
	RawlogRecord r;
	const auto odo = sf.getObservationByClass<mrpt::obs::CObservationOdometry>();
	const auto head = sf.getObservationByClass<mrpt::obs::CObservationRawDAQ>();
	const auto gt = sf.getObservationByClass<mrpt::obs::CObservationRobotPose>();
	if (!odo || !head) fail(path, i, "missing ODOMETRY or HEAD_ANGLES");
	if (head->AIN_double.size() != 4) fail(path, i, "HEAD_ANGLES must hold 4 values");
	r.time_s = timeOf(odo->timestamp);
	r.odometry_zxphi = geometry::vehicleFromMrpt(odo->odometry);
	r.ticks_right = odo->encoderRightTicks;
	r.ticks_left = odo->encoderLeftTicks;
	r.head_rad = Eigen::Vector4d(head->AIN_double.data());
	if (gt) r.true_zxphi = geometry::vehicleFromMrpt(mrpt::poses::CPose2D(gt->pose.mean));
	if (const auto s = sf.getObservationByClass<mrpt::obs::CObservationStereoImages>())
		readStereo(*s, r, images);
	return r;
}
}  // namespace

namespace
{
/** True when the first record of @p path is an observation (observations-only format). */
bool observationsOnly(const std::string& path)
{
	mrpt::io::CFileGZInputStream file;
	if (!file.open(path)) return false;
	try
	{
		auto in = mrpt::serialization::archiveFrom(file);
		return std::dynamic_pointer_cast<mrpt::obs::CObservation>(in.ReadObject()) != nullptr;
	}
	catch (const std::exception&)
	{
		return false;
	}
}
}  // namespace

std::vector<RawlogRecord> readRawlog(const std::string& path, ImageLoading images)
{
	if (std::filesystem::exists(path) && observationsOnly(path))
		return recordsOf(readObservationLog(path), path, images);
	mrpt::io::CFileGZInputStream file;
	if (!std::filesystem::exists(path) || !file.open(path))
		throw std::runtime_error("cannot read rawlog " + path);
	// MRPT 2.5.8 joins the folder of an absolute rawlog path without a separator: set it here
	mrpt::img::CImage::setImagesPathBase(imagesDirFor(path));
	auto in = mrpt::serialization::archiveFrom(file);
	std::vector<RawlogRecord> out;
	mrpt::obs::CActionCollection::Ptr acts;
	mrpt::obs::CSensoryFrame::Ptr sf;
	size_t pos = 0;
	while (mrpt::obs::CRawlog::readActionObservationPair(in, acts, sf, pos))
	{
		if (!sf) fail(path, out.size(), "not an action/observation pair");
		out.push_back(recordOf(*sf, path, out.size(), images));
	}
	if (out.empty() && std::filesystem::file_size(path) > 0)
		throw std::runtime_error(path + ": not a rawlog (its first record is unreadable)");
	return out;
}

}  // namespace mrolr::io
