#include <mrolr/hw_serial/SerialError.h>

namespace mrolr::hw
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
    : std::runtime_error(device + " on " + port + ": " + kindName(kind) + ": " + what_happened),
      kind_(kind),
      device_(device),
      port_(port)
{
}

}  // namespace mrolr::hw
