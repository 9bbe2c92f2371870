#include <mrolr/hw_serial/CameraSensorStereo.h>
#include <mrolr/hw_serial/GreyImage.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/util/Config.h>

#include <mrpt/hwdrivers/CCameraSensor.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <regex>
#include <sstream>

namespace mrolr::hw_serial
{
namespace
{
/** The grabber types CCameraSensor::initialize of MRPT 2.5.8 knows. */
const char* const kGrabberTypes[] = {
    "opencv",  "dc1394",    "bumblebee_dc1394", "svs",    "ffmpeg",        "swissranger", "kinect",
    "openni2", "image_dir", "rawlog",           "flycap", "flycap_stereo", "duo3d",       "myntd"};

std::string grabberType(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	// CCameraSensor would silently take opencv for a missing key; a camera is chosen explicitly
	if (!util::hasKey(cfg, section, "grabber_type"))
		throw util::ConfigError(util::describeKey(cfg, section, "grabber_type") +
		                        ": missing; each camera needs a section in CCameraSensor's "
		                        "format, e.g. grabber_type = opencv and cv_camera_index = 0");
	const std::string type =
	    mrpt::system::lowerCase(mrpt::system::trim(util::readString(cfg, section, "grabber_type")));
	const auto* end = std::end(kGrabberTypes);
	if (std::find(std::begin(kGrabberTypes), end, type) == end)
		throw util::ConfigError(util::describeKey(cfg, section, "grabber_type") + ": '" + type +
		                        "' is not a CCameraSensor grabber (opencv, image_dir, rawlog, "
		                        "dc1394, ffmpeg, flycap, ...)");
	return type;
}

/** MRPT formats the file name with printf and one int: any other conversion would read memory
 * that is not there, so the format is checked before MRPT uses it. */
void requireIndexFormat(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                        const std::string& key, const std::string& format)
{
	static const std::regex one_int("([^%]|%%)*%0?[0-9]{0,2}d([^%]|%%)*");
	if (!std::regex_match(format, one_int))
		throw util::ConfigError(util::describeKey(cfg, section, key) + ": '" + format +
		                        "' must hold exactly one integer conversion such as %04d");
}

/** What printf gives for a format requireIndexFormat accepted and @p index, without handing a
 * format from a file to printf. */
std::string formatIndex(const std::string& format, long index)
{
	std::ostringstream out;
	for (size_t i = 0; i < format.size(); ++i)
	{
		if (format[i] != '%')
			out << format[i];
		else if (format[i + 1] == '%')
			out << '%', ++i;
		else
		{
			const bool zero = format[++i] == '0';
			if (zero) ++i;
			int width = 0;
			while (std::isdigit(static_cast<unsigned char>(format[i])))
				width = 10 * width + (format[i++] - '0');
			out << std::setw(width) << std::setfill(zero ? '0' : ' ')
			    << (zero ? std::internal : std::right) << index;  // format[i] is the 'd'
		}
	}
	return out.str();
}

std::string sourceOf(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                     const std::string& type)
{
	if (type == "opencv")
		return "opencv camera " + cfg.read_string(section, "cv_camera_index", "0");
	if (type == "image_dir") return "image_dir " + cfg.read_string(section, "image_dir_url", "");
	if (type == "rawlog") return "rawlog " + cfg.read_string(section, "rawlog_file", "");
	return type;
}
}  // namespace

struct CameraSensorStereo::Camera
{
	std::string section, source;
	mrpt::hwdrivers::CCameraSensor sensor;

	Camera(const mrpt::config::CConfigFileBase& cfg, const std::string& section_name);
	void checkImageDir(const mrpt::config::CConfigFileBase& cfg) const;
	mrpt::img::CImage grab(double& time_s);
	[[noreturn]] void fail(SerialDeviceError::Kind kind, const std::string& what) const
	{
		throw SerialDeviceError(kind, section, source, what);
	}
};

CameraSensorStereo::Camera::Camera(const mrpt::config::CConfigFileBase& cfg,
                                   const std::string& section_name)
    : section(section_name)
{
	const std::string type = grabberType(cfg, section);
	source = sourceOf(cfg, section, type);
	try
	{
		sensor.loadConfig(cfg, section);
	}
	catch (const std::exception& e)
	{
		throw util::ConfigError(util::describeKey(cfg, section, "grabber_type") +
		                        ": CCameraSensor refuses the section: " + mrptMessage(e.what()));
	}
	if (type == "image_dir") checkImageDir(cfg);
	try
	{
		sensor.initialize();
	}
	catch (const std::exception& e)
	{
		fail(SerialDeviceError::Kind::Disconnected,
		     "cannot open the camera: " + mrptMessage(e.what()));
	}
}

/** The image_dir grabber opens nothing until its first grab; its folder and first image are
 * checked here so that a missing one fails before the robot moves. */
void CameraSensorStereo::Camera::checkImageDir(const mrpt::config::CConfigFileBase& cfg) const
{
	if (!cfg.read_string(section, "right_format", "").empty())
		throw util::ConfigError(util::describeKey(cfg, section, "right_format") +
		                        ": one camera per section; leave right_format out");
	const std::string dir = cfg.read_string(section, "image_dir_url", "");
	if (dir.find('%') != std::string::npos)
		throw util::ConfigError(util::describeKey(cfg, section, "image_dir_url") +
		                        ": CCameraSensor would read the '%' in the folder as a printf "
		                        "conversion");
	const std::string format = mrpt::system::trim(cfg.read_string(section, "left_format", ""));
	requireIndexFormat(cfg, section, "left_format", format);
	if (!mrpt::system::directoryExists(dir))
		fail(SerialDeviceError::Kind::Disconnected, "no folder '" + dir + "'");
	const long first = util::readInt(cfg, section, "start_index", 0);
	const std::string file = dir + "/" + formatIndex(format, first);
	if (!mrpt::system::fileExists(file))
		fail(SerialDeviceError::Kind::Disconnected, "no first image '" + file + "'");
}

mrpt::img::CImage CameraSensorStereo::Camera::grab(double& time_s)
{
	std::vector<mrpt::serialization::CSerializable::Ptr> frames;
	try
	{
		sensor.getNextFrame(frames);
	}
	catch (const std::exception& e)
	{
		fail(SerialDeviceError::Kind::Disconnected, "no frame: " + mrptMessage(e.what()));
	}
	const auto image = frames.size() == 1
	                       ? std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(frames[0])
	                       : nullptr;
	if (!image)
		fail(SerialDeviceError::Kind::Garbage, "the grabber delivered no single image (" +
		                                           std::to_string(frames.size()) +
		                                           " observations; one camera per section)");
	time_s = mrpt::Clock::toDouble(image->timestamp);
	try
	{
		return greyCopy(image->image, "the frame");
	}
	catch (const std::invalid_argument& e)
	{
		fail(SerialDeviceError::Kind::Garbage, e.what());
	}
}

CameraSensorStereo::CameraSensorStereo(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
    : left_(std::make_unique<Camera>(cfg, section + ".left")),
      right_(std::make_unique<Camera>(cfg, section + ".right"))
{
}

CameraSensorStereo::~CameraSensorStereo() = default;

hw::StereoImages CameraSensorStereo::grab()
{
	hw::StereoImages out;
	double right_time_s = 0;
	out.left = left_->grab(out.time_s);
	out.right = right_->grab(right_time_s);
	return out;
}

std::string CameraSensorStereo::leftSource() const
{
	return left_->source;
}
std::string CameraSensorStereo::rightSource() const
{
	return right_->source;
}

}  // namespace mrolr::hw_serial
