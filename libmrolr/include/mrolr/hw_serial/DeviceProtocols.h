#pragma once
/** The device side of the three protocols (docs/serial.md): each handler executes one request on
 * an hw:: device (the simulated one, or any other implementation) and returns the reply fields.
 * Pure: no I/O; ProtocolServer adds framing, sequence numbers and error replies.
 *
 * | device  | request                         | reply fields                    |
 * |---------|---------------------------------|---------------------------------|
 * | all     | `ID?`                           | `LABMATE` / `BISIGHT` / `RTX`, `1` |
 * | base    | `STEP v1_mps v2_mps dt_s`       | (none)                          |
 * | base    | `ODO?`                          | `z_m x_m phi_rad ticks_r ticks_l t_s` |
 * | head    | `MOVE pan tilt verg_l verg_r` (rad) | `settle_s`                  |
 * | head    | `ANG?`                          | `pan tilt verg_l verg_r` (rad)  |
 * | arm     | `MOVE d1_mm q1..q6_deg`         | (none)                          |
 * | arm     | `JNT?`                          | `d1_mm q1..q6_deg`              |
 * | arm     | `GRIP 0` / `GRIP 1` (open/close)| (none)                          |
 * | arm     | `GRIP?`                         | `0` / `1`                       |
 */

#include <mrolr/hw/Devices.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mrolr::hw_serial
{
/** A request the handler refuses; code is one of errcode::*. */
class CommandError : public std::runtime_error
{
 public:
	CommandError(std::string code, const std::string& text)
	    : std::runtime_error(text), code_(std::move(code))
	{
	}
	const std::string& code() const { return code_; }

 private:
	std::string code_;
};

/** Wire names of the devices, the first field of the `ID?` reply. */
constexpr const char* kBaseId = "LABMATE";
constexpr const char* kHeadId = "BISIGHT";
constexpr const char* kArmId = "RTX";

class RequestHandler
{
 public:
	virtual ~RequestHandler() = default;
	/** Executes @p verb; throws CommandError (BADCMD, BADARG, LIMIT) or lets the device's own
	 * exception through (ProtocolServer maps it to LIMIT or FAULT). */
	virtual std::vector<std::string> execute(const std::string& verb,
	                                         const std::vector<std::string>& args) = 0;
};

class BaseHandler : public RequestHandler
{
 public:
	explicit BaseHandler(hw::BaseDevice& device) : device_(device) {}
	std::vector<std::string> execute(const std::string& verb,
	                                 const std::vector<std::string>& args) override;

 private:
	hw::BaseDevice& device_;
};

class HeadHandler : public RequestHandler
{
 public:
	explicit HeadHandler(hw::HeadDevice& device) : device_(device) {}
	std::vector<std::string> execute(const std::string& verb,
	                                 const std::vector<std::string>& args) override;

 private:
	hw::HeadDevice& device_;
};

class ArmHandler : public RequestHandler
{
 public:
	explicit ArmHandler(hw::ArmDevice& device) : device_(device) {}
	std::vector<std::string> execute(const std::string& verb,
	                                 const std::vector<std::string>& args) override;

 private:
	hw::ArmDevice& device_;
};

/** Numbers as reply fields (formatNumber each). */
std::vector<std::string> numberFields(const std::vector<double>& values);

/** parseNumbers, turning its std::invalid_argument into CommandError(BADARG). */
std::vector<double> requireNumbers(const std::vector<std::string>& args, size_t count,
                                   const std::string& verb);

}  // namespace mrolr::hw_serial
