#include <mrolr/hw_serial/SerialError.h>

namespace mrolr::hw_serial
{
const char* kindName(SerialDeviceError::Kind kind)
{
	switch (kind)
	{
		case SerialDeviceError::Kind::Timeout:
			return "timeout";
		case SerialDeviceError::Kind::Garbage:
			return "garbage";
		case SerialDeviceError::Kind::Disconnected:
			return "disconnected";
		case SerialDeviceError::Kind::Refused:
			return "refused";
	}
	return "?";
}

SerialDeviceError::SerialDeviceError(Kind kind, const std::string& device, const std::string& port,
                                     const std::string& what_happened)
    : hw::DeviceFailure(device + " on " + port + ": " + kindName(kind) + ": " + what_happened),
      kind_(kind),
      device_(device),
      port_(port)
{
}

std::string mrptMessage(const std::string& what)
{
	// a nested MRPT exception repeats the header; the innermost message names the cause
	const size_t m = what.rfind("Message:");
	if (m == std::string::npos) return what.substr(0, what.find('\n'));
	const size_t start = what.find_first_not_of(' ', m + 8);
	if (start == std::string::npos) return {};
	return what.substr(start, what.find('\n', start) - start);
}

}  // namespace mrolr::hw_serial
