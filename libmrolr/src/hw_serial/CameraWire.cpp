#include <mrolr/hw_serial/CameraWire.h>
#include <mrolr/hw_serial/Framing.h>
#include <mrolr/hw_serial/GreyImage.h>
#include <mrolr/hw_serial/SerialError.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

namespace mrolr::hw_serial
{
namespace
{
constexpr size_t kMaxErrorBytes = 4096;

const char* magicOf(CameraFrameKind kind)
{
	switch (kind)
	{
		case CameraFrameKind::Request:
			return "MRCQ";
		case CameraFrameKind::Images:
			return "MRCI";
		case CameraFrameKind::Error:
			return "MRCE";
	}
	return "????";
}

void putU32(std::string& out, uint32_t v)
{
	for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
}

uint32_t getU32(std::string_view bytes, size_t at)
{
	uint32_t v = 0;
	for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(bytes[at + size_t(i)])) << (8 * i);
	return v;
}

CameraFrameKind kindOf(std::string_view magic)
{
	for (auto k : {CameraFrameKind::Request, CameraFrameKind::Images, CameraFrameKind::Error})
		if (magic == magicOf(k)) return k;
	throw CameraWireError("not a camera frame: header '" + printableBytes(magic) + "'");
}

/** MRPT's clock cannot hold negative or non-finite times (its conversion is to unsigned ticks). */
mrpt::Clock::time_point observationTime(double time_s)
{
	if (!std::isfinite(time_s) || time_s < 0) return INVALID_TIMESTAMP;
	return mrpt::Clock::fromDouble(time_s);
}

mrpt::obs::CObservationStereoImages toObservation(const hw::StereoImages& images)
{
	mrpt::obs::CObservationStereoImages obs;
	obs.imageLeft = greyCopy(images.left, "the left image");
	obs.imageRight = greyCopy(images.right, "the right image");
	obs.hasImageRight = true;
	obs.hasImageDisparity = false;
	obs.timestamp = observationTime(images.time_s);
	obs.sensorLabel = kCameraSensorLabel;
	return obs;
}

bool isGrey8(const mrpt::img::CImage& im)
{
	return !im.isExternallyStored() && !im.isEmpty() && !im.isColor() &&
	       im.getPixelDepth() == mrpt::img::PixelDepth::D8U;
}

hw::StereoImages readPayload(std::string_view payload)
{
	mrpt::io::CMemoryStream mem;
	mem.assignMemoryNotOwn(payload.data(), payload.size());
	auto in = mrpt::serialization::archiveFrom(mem);
	hw::StereoImages out;
	in >> out.time_s >> out.angles.pan >> out.angles.tilt >> out.angles.verg_left >>
	    out.angles.verg_right >> out.frame;
	mrpt::obs::CObservationStereoImages obs;
	in.ReadObject(&obs);
	if (mem.getPosition() != payload.size())
		throw CameraWireError(std::to_string(payload.size() - mem.getPosition()) +
		                      " bytes left over after the observation");
	if (!obs.hasImageRight || !isGrey8(obs.imageLeft) || !isGrey8(obs.imageRight))
		throw CameraWireError("the observation lacks an 8-bit grey left or right image");
	out.left = obs.imageLeft;
	out.right = obs.imageRight;
	return out;
}
}  // namespace

std::string encodeCameraHeader(const CameraFrameHeader& header)
{
	std::string out = magicOf(header.kind);
	putU32(out, header.seq);
	putU32(out, header.length);
	return out;
}

CameraFrameHeader decodeCameraHeader(std::string_view bytes)
{
	if (bytes.size() < kCameraHeaderBytes)
		throw std::invalid_argument("decodeCameraHeader: fewer than 12 bytes");
	CameraFrameHeader h;
	h.kind = kindOf(bytes.substr(0, 4));
	h.seq = getU32(bytes, 4);
	h.length = getU32(bytes, 8);
	if (h.length > kCameraMaxPayloadBytes)
		throw CameraWireError("frame announces " + std::to_string(h.length) +
		                      " payload bytes, more than the limit of " +
		                      std::to_string(kCameraMaxPayloadBytes));
	if (h.kind == CameraFrameKind::Request && h.length != 0)
		throw CameraWireError("a request frame with a payload");
	return h;
}

std::string encodeCameraRequest(uint32_t seq)
{
	return encodeCameraHeader({CameraFrameKind::Request, seq, 0});
}

std::string encodeCameraImages(uint32_t seq, const hw::StereoImages& images)
{
	const auto obs = toObservation(images);
	mrpt::io::CMemoryStream mem;
	auto out = mrpt::serialization::archiveFrom(mem);
	out << images.time_s << images.angles.pan << images.angles.tilt << images.angles.verg_left
	    << images.angles.verg_right << images.frame;
	out << obs;
	const auto n = size_t(mem.getTotalBytesCount());
	if (n > kCameraMaxPayloadBytes)
		throw std::invalid_argument("the stereo pair needs " + std::to_string(n) +
		                            " bytes, more than the camera socket's limit");
	std::string frame = encodeCameraHeader({CameraFrameKind::Images, seq, uint32_t(n)});
	frame.append(static_cast<const char*>(mem.getRawBufferData()), n);
	return frame;
}

std::string encodeCameraError(uint32_t seq, std::string_view message)
{
	const auto text = message.substr(0, kMaxErrorBytes);
	std::string frame = encodeCameraHeader({CameraFrameKind::Error, seq, uint32_t(text.size())});
	frame.append(text);
	return frame;
}

hw::StereoImages decodeCameraImages(std::string_view payload)
{
	try
	{
		return readPayload(payload);
	}
	catch (const CameraWireError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw CameraWireError("the payload is not a serialized stereo pair: " +
		                      mrptMessage(e.what()));
	}
}

}  // namespace mrolr::hw_serial
