#pragma once
/** The head's two real cameras through mrpt::hwdrivers::CCameraSensor: a frame grabber for
 * SerialHead on the robot (docs/serial.md "Real cameras"). */

#include <mrolr/hw/Devices.h>

#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>

namespace mrolr::hw_serial
{
/** Opens the left camera from the section `<section>.left` and the right one from
 * `<section>.right` of an .ini, each in CCameraSensor's own format (grabber_type = opencv with
 * cv_camera_index, image_dir with image_dir_url, left_format, start_index, end_index, rawlog
 * with rawlog_file, ...; one camera per section). grab() reads one frame from each, converted to
 * 8-bit grey; the head angles are left default for the caller (SerialHead stamps them).
 *
 * Errors, all from the constructor before anything moves when the cameras are missing:
 * util::ConfigError (a section or grabber_type missing, an unknown grabber_type, a malformed
 * image_dir format, a value CCameraSensor refuses) names file, section and key;
 * SerialDeviceError Disconnected, with the section as device and the source ("opencv camera 3",
 * "image_dir /data/left") as port, when a camera cannot be opened — or, from grab(), delivers no
 * frame any more; SerialDeviceError Garbage when it delivers something that is not one image. */
class CameraSensorStereo
{
 public:
	explicit CameraSensorStereo(const mrpt::config::CConfigFileBase& cfg,
	                            const std::string& section = "device.camera");
	~CameraSensorStereo();
	CameraSensorStereo(const CameraSensorStereo&) = delete;
	CameraSensorStereo& operator=(const CameraSensorStereo&) = delete;

	/** One frame from each camera, 8-bit grey; time_s = the left frame's timestamp in seconds
	 * (UNIX time, as mrpt::Clock::toDouble gives it). */
	hw::StereoImages grab();

	/** The left and right cameras' sources for messages ("opencv camera 0"). */
	std::string leftSource() const;
	std::string rightSource() const;

 private:
	struct Camera;
	std::unique_ptr<Camera> left_, right_;
};

}  // namespace mrolr::hw_serial
