// Device calls ⇄ rawlog observations (DeviceCall.h).
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/DeviceCall.h>

#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <mrolr/io/Rawlog.h>

#include <array>
#include <filesystem>
#include <cstdio>
#include <sstream>

namespace mrolr::mission
{
namespace
{
struct CallInfo
{
	CallKind kind;
	const char* label;
	const char* name;  ///< device.request
	size_t request, answer;  ///< how many values each holds
};

constexpr std::array<CallInfo, 12> kCalls{{
    {CallKind::BaseStep, "BASE_STEP", "base.step", 3, 0},
    {CallKind::BaseOdometry, "BASE_ODOMETRY", "base.odometry", 0, 7},
    {CallKind::HeadMove, "HEAD_MOVE", "head.moveTo", 4, 1},
    {CallKind::HeadAngles, "HEAD_ANGLES", "head.angles", 0, 4},
    {CallKind::HeadGrab, "HEAD_GRAB", "head.grab", 0, 6},
    {CallKind::ArmMove, "ARM_MOVE", "arm.moveTo", 7, 0},
    {CallKind::ArmJoints, "ARM_JOINTS", "arm.joints", 0, 7},
    {CallKind::ArmGripper, "GRIPPER", "arm.setGripper", 1, 0},
    {CallKind::ArmGripperClosed, "GRIPPER_CLOSED", "arm.gripperClosed", 0, 1},
    {CallKind::ArmGripperWidth, "GRIPPER_WIDTH", "arm.gripperWidthMm", 0, 1},
    {CallKind::ArmDock, "ARM_DOCK", "arm.dock", 1, 0},
    {CallKind::ArmDocked, "ARM_DOCKED", "arm.docked", 0, 1},
}};

const CallInfo& info(CallKind k)
{
	return kCalls.at(static_cast<size_t>(k));
}

mrpt::poses::CPose3DQuat poseOf(const Eigen::Isometry3d& T)
{
	mrpt::math::CMatrixDouble44 H;
	H.asEigen() = T.matrix();
	return mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(H));
}

/** The pair of a grab, with the cameras where the head's calibration puts them at its angles. */
mrpt::obs::CObservation::Ptr stereoOf(const DeviceCall& c, size_t index,
                                      const geometry::BiSightHead& head,
                                      const io::ObservationLogWriter& log)
{
	auto o = mrpt::obs::CObservationStereoImages::Create();
	o->sensorLabel = "BISIGHT";
	o->timestamp = io::stampOf(c.time_s);
	char name[64];
	std::snprintf(name, sizeof(name), "BISIGHT_%07zu", index);
	o->imageLeft = log.external(c.images->left, std::string(name) + "_left.png");
	o->imageRight = log.external(c.images->right, std::string(name) + "_right.png");
	o->hasImageRight = true;
	o->leftCamera = o->rightCamera = head.camera().toTCamera();
	const auto& a = c.images->angles;
	const Eigen::Isometry3d T_C0inV = geometry::T_C0inW({0, 0, 0}, head.options().head_height_m);
	const auto L = head.T_CamCvInC0(geometry::Side::Left, a);
	o->cameraPose = mrpt::poses::CPose3DQuat(geometry::cameraPoseToMrpt(T_C0inV * L));
	o->rightCameraPose = poseOf(L.inverse() * head.T_CamCvInC0(geometry::Side::Right, a));
	return o;
}
}  // namespace

std::vector<double> valuesOf(const geometry::HeadAngles& a)
{
	return {a.pan, a.tilt, a.verg_left, a.verg_right};
}

geometry::HeadAngles anglesFrom(const std::vector<double>& v)
{
	return {v.at(0), v.at(1), v.at(2), v.at(3)};
}

const char* labelOf(CallKind kind)
{
	return info(kind).label;
}

std::optional<CallKind> callOfLabel(const std::string& label)
{
	for (const auto& c : kCalls)
		if (label == c.label) return c.kind;
	return std::nullopt;
}

std::string describe(CallKind kind, const std::vector<double>& request)
{
	std::ostringstream s;
	s.precision(17);
	s << info(kind).name << "(";
	for (size_t i = 0; i < request.size(); ++i) s << (i ? ", " : "") << request[i];
	s << ")";
	return s.str();
}

DeviceFault faultOf(const std::exception& e)
{
	if (const auto* s = dynamic_cast<const hw_serial::SerialDeviceError*>(&e))
		return {std::string("SerialDeviceError\t") + hw_serial::kindName(s->kind()) + "\t" + s->device() +
		            "\t" + s->port(),
		        e.what()};
	if (dynamic_cast<const hw::ReplayDivergence*>(&e)) return {"ReplayDivergence", e.what()};
	if (dynamic_cast<const hw::DeviceFailure*>(&e)) return {"DeviceFailure", e.what()};
	if (dynamic_cast<const hw::ArmBlocked*>(&e)) return {"ArmBlocked", e.what()};
	if (dynamic_cast<const geometry::FixationError*>(&e)) return {"FixationError", e.what()};
	if (dynamic_cast<const geometry::ProjectionError*>(&e)) return {"ProjectionError", e.what()};
	if (dynamic_cast<const geometry::TriangulationError*>(&e))
		return {"TriangulationError", e.what()};
	if (dynamic_cast<const geometry::GeometryError*>(&e)) return {"GeometryError", e.what()};
	if (dynamic_cast<const std::invalid_argument*>(&e)) return {"invalid_argument", e.what()};
	if (dynamic_cast<const std::out_of_range*>(&e)) return {"out_of_range", e.what()};
	if (dynamic_cast<const std::logic_error*>(&e)) return {"logic_error", e.what()};
	return {"runtime_error", e.what()};
}

namespace
{
[[noreturn]] void rethrowSerial(const std::string& type, const std::string& message)
{
	std::vector<std::string> f;
	std::istringstream in(type);
	for (std::string part; std::getline(in, part, '\t');) f.push_back(part);
	if (f.size() != 4) throw std::runtime_error("malformed recorded fault type '" + type + "'");
	using Kind = hw_serial::SerialDeviceError::Kind;
	Kind kind = Kind::Timeout;
	for (Kind k : {Kind::Timeout, Kind::Garbage, Kind::Disconnected, Kind::Refused})
		if (f[1] == hw_serial::kindName(k)) kind = k;
	// the message is "<device> on <port>: <kind>: <what happened>"; rebuild it from its parts
	const std::string prefix = f[2] + " on " + f[3] + ": " + f[1] + ": ";
	const std::string what =
	    message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
	throw hw_serial::SerialDeviceError(kind, f[2], f[3], what);
}
}  // namespace

void rethrow(const DeviceFault& f)
{
	const auto& m = f.message;
	if (f.type.rfind("SerialDeviceError", 0) == 0) rethrowSerial(f.type, m);
	if (f.type == "ReplayDivergence") throw hw::ReplayDivergence(m);
	if (f.type == "DeviceFailure") throw hw::DeviceFailure(m);
	if (f.type == "ArmBlocked") throw hw::ArmBlocked(m);
	if (f.type == "FixationError") throw geometry::FixationError(m);
	if (f.type == "ProjectionError") throw geometry::ProjectionError(m);
	if (f.type == "TriangulationError") throw geometry::TriangulationError(m);
	if (f.type == "GeometryError") throw geometry::GeometryError(m);
	if (f.type == "invalid_argument") throw std::invalid_argument(m);
	if (f.type == "out_of_range") throw std::out_of_range(m);
	if (f.type == "logic_error") throw std::logic_error(m);
	throw std::runtime_error(m);
}

std::vector<mrpt::obs::CObservation::Ptr> observationsOf(const DeviceCall& c, size_t index,
                                                         const geometry::BiSightHead& head,
                                                         const io::ObservationLogWriter& log)
{
	std::vector<mrpt::obs::CObservation::Ptr> out;
	if (c.images) out.push_back(stereoOf(c, index, head, log));
	if (c.fault)
	{
		out.push_back(io::labelledComment(kFaultLabel, c.fault->type + "\n" + c.fault->message,
		                                  io::stampOf(c.time_s)));
	}
	auto daq = mrpt::obs::CObservationRawDAQ::Create();
	daq->sensorLabel = labelOf(c.kind);
	daq->timestamp = io::stampOf(c.time_s);
	daq->AOUT_double = c.request;
	daq->AIN_double = c.answer;
	daq->AIN_channel_count = static_cast<uint16_t>(c.answer.size());
	out.push_back(daq);
	return out;
}

namespace
{
[[noreturn]] void malformed(const std::string& path, size_t record, const std::string& label,
                            const std::string& why)
{
	throw std::runtime_error(path + ": record " + std::to_string(record) + " (" + label +
	                         "): " + why);
}

hw::StereoImages pairOf(const mrpt::obs::CObservationStereoImages& s, const std::string& path)
{
	hw::StereoImages p;  // the pixels stay in their files until the replay asks (loadPair)
	for (const auto* img : {&s.imageLeft, &s.imageRight})
	{
		const auto file = std::filesystem::path(io::imagesDirFor(path)) / img->getExternalStorageFile();
		if (!img->isExternallyStored() || !std::filesystem::exists(file))
			throw std::runtime_error(path + ": the image " + file.string() +
			                         " of a recorded pair is missing");
	}
	p.left = s.imageLeft;
	p.right = s.imageRight;
	return p;
}

/** The call of record @p i, with the pair and fault that came before it. */
DeviceCall callOf(const mrpt::obs::CObservationRawDAQ& daq, CallKind kind,
                  std::optional<hw::StereoImages>& pair, std::optional<DeviceFault>& fault,
                  const std::string& path, size_t i)
{
	const auto& in = info(kind);
	DeviceCall c{kind, daq.AOUT_double, daq.AIN_double, std::nullopt, std::move(fault),
	             io::timeOf(daq.timestamp)};
	fault.reset();
	if (c.request.size() != in.request)
		malformed(path, i, in.label, "holds " + std::to_string(c.request.size()) +
		                                 " request values, expected " + std::to_string(in.request));
	if (!c.fault && c.answer.size() != in.answer)
		malformed(path, i, in.label, "holds " + std::to_string(c.answer.size()) +
		                                 " answer values, expected " + std::to_string(in.answer));
	if (kind == CallKind::HeadGrab && !c.fault)
	{
		if (!pair) malformed(path, i, in.label, "a grab without its BISIGHT pair before it");
		c.images = std::move(pair);
		const auto& a = c.answer;
		c.images->angles = {a[0], a[1], a[2], a[3]};
		c.images->time_s = a[4];
		c.images->frame = static_cast<uint64_t>(a[5]);
	}
	pair.reset();
	return c;
}

std::optional<DeviceFault> faultOfComment(const std::string& text)
{
	const auto nl = text.find('\n');
	if (nl == std::string::npos) return DeviceFault{text, ""};
	return DeviceFault{text.substr(0, nl), text.substr(nl + 1)};
}
}  // namespace

RecordedCalls readDeviceCalls(const std::string& path)
{
	auto log = io::readObservationLog(path);
	RecordedCalls out;
	out.torn = log.torn;
	out.path = path;
	std::optional<hw::StereoImages> pair;
	std::optional<DeviceFault> fault;
	for (size_t i = 0; i < log.observations.size(); ++i)
	{
		const auto& obs = log.observations[i];
		if (const auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(obs);
		    s && s->sensorLabel == "BISIGHT")
			pair = pairOf(*s, path);
		else if (const auto m = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obs))
		{
			if (m->sensorLabel == kFaultLabel) fault = faultOfComment(m->text);
			if (m->sensorLabel == kStopLabel) out.stops_before.push_back(out.calls.size());
		}
		else if (const auto d = std::dynamic_pointer_cast<mrpt::obs::CObservationRawDAQ>(obs))
			if (const auto kind = callOfLabel(d->sensorLabel))
				out.calls.push_back(callOf(*d, *kind, pair, fault, path, i));
	}
	return out;
}

hw::StereoImages loadPair(const hw::StereoImages& recorded, const std::string& rawlog_path)
{
	hw::StereoImages p = recorded;
	p.left = io::loadExternal(recorded.left, rawlog_path);
	p.right = io::loadExternal(recorded.right, rawlog_path);
	return p;
}

}  // namespace mrolr::mission
