#pragma once
/** The frames of the camera socket (docs/serial.md "The camera socket"), shared by CameraServer
 * and CameraSocketClient; pure functions, no I/O, so the format is tested without sockets.
 *
 * Every frame, in both directions, is a 12-byte header followed by its payload:
 *
 *   bytes 0..3   magic, 4 ASCII bytes: "MRCQ" request, "MRCI" stereo images, "MRCE" error
 *   bytes 4..7   seq, uint32 little-endian: chosen by the client, echoed by the server
 *   bytes 8..11  length, uint32 little-endian: payload bytes (0 for a request), at most
 *                kCameraMaxPayloadBytes
 *
 * The MRCI payload is one MRPT archive (mrpt::serialization::archiveFrom on a memory stream):
 * five doubles — time_s, then the head angles of the grab pan, tilt, verg_left, verg_right in
 * radians (geometry::HeadAngles) — followed by one serialized mrpt::obs::CObservationStereoImages
 * holding the left and the right 8-bit greyscale images (raw pixels: MRPT stores grey images
 * uncompressed), hasImageRight = true, no disparity, its timestamp = time_s at MRPT's 100 ns
 * resolution and sensorLabel kCameraSensorLabel. The exact time_s and the angles travel as the
 * doubles because the observation has no field for joint angles and its clock rounds the time.
 * Camera intrinsics and poses are not sent: the robot has its own calibration.
 * The MRCE payload is the server's message (why the grab failed), as plain bytes.
 */

#include <mrolr/hw/Devices.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mrolr::hw_serial
{
/** Kinds of frames, by their magic. */
enum class CameraFrameKind
{
	Request,  ///< "MRCQ": grab one pair now; no payload
	Images,   ///< "MRCI": the pair
	Error     ///< "MRCE": the server could not grab; payload = its message
};

/** Bytes of every frame header. */
constexpr size_t kCameraHeaderBytes = 12;
/** Larger payloads are refused before anything is allocated: two 8-bit 4096 x 4096 images with
 * room to spare, far beyond a camera of the head, so a garbage length is caught at once. */
constexpr uint32_t kCameraMaxPayloadBytes = 64u << 20;
/** The observation's sensorLabel. */
constexpr const char* kCameraSensorLabel = "HEAD_STEREO";

/** A frame that cannot be read: unknown magic, overlong length, payload that does not
 * deserialize. The client reports it as SerialDeviceError Garbage. */
class CameraWireError : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

struct CameraFrameHeader
{
	CameraFrameKind kind = CameraFrameKind::Request;
	uint32_t seq = 0;
	uint32_t length = 0;  ///< payload bytes
};

std::string encodeCameraHeader(const CameraFrameHeader& header);
/** Reads the first kCameraHeaderBytes of @p bytes; throws CameraWireError on an unknown magic
 * (quoting the bytes), a length above kCameraMaxPayloadBytes or a request with a payload, and
 * std::invalid_argument when fewer bytes are given. */
CameraFrameHeader decodeCameraHeader(std::string_view bytes);

/** The whole request frame. */
std::string encodeCameraRequest(uint32_t seq);
/** The whole MRCI frame. Throws std::invalid_argument when an image is empty or not 8-bit;
 * colour is converted to grey (greyCopy). */
std::string encodeCameraImages(uint32_t seq, const hw::StereoImages& images);
/** The whole MRCE frame (the message cut to 4096 bytes). */
std::string encodeCameraError(uint32_t seq, std::string_view message);

/** The pair of an MRCI payload: images (8-bit grey), angles and time_s exactly as sent. Throws
 * CameraWireError when the bytes do not deserialize, hold another class, leave bytes over, or
 * lack an 8-bit grey right or left image. */
hw::StereoImages decodeCameraImages(std::string_view payload);

}  // namespace mrolr::hw_serial
