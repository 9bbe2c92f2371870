#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/hw_serial/ProtocolServer.h>

#include <chrono>

namespace mrolr::hw_serial
{
namespace
{
constexpr int kPollMs = 20;  ///< the loop checks for stop() at least this often
}

DeviceEmulator::DeviceEmulator(ByteTransport& link, RequestHandler& handler,
                               const FaultOptions& faults)
    : link_(link), handler_(handler), faults_(faults), rng_(faults.seed)
{
	thread_ = std::thread([this] { loop(); });
}

DeviceEmulator::~DeviceEmulator()
{
	stop();
}

void DeviceEmulator::setFaults(const FaultOptions& faults)
{
	std::lock_guard<std::mutex> lock(mutex_);
	faults_ = faults;
	rng_.seed(faults.seed);
}

void DeviceEmulator::stop()
{
	stop_ = true;
	if (thread_.joinable()) thread_.join();
}

void DeviceEmulator::loop()
{
	ProtocolServer server(handler_);
	LineAssembler assembler;
	try
	{
		while (!stop_)
		{
			assembler.feed(link_.read(kPollMs));
			AssembledLine line;
			while (!stop_ && assembler.next(line)) serveLine(server, line);
		}
	}
	catch (const TransportClosed&)
	{
		// the host went away: nothing left to serve
	}
}

void DeviceEmulator::serveLine(ProtocolServer& server, const AssembledLine& line)
{
	++received_;
	if (silent()) return;  // a hung device: neither executes nor answers
	const std::string full = server.handleLine(line);
	executed_ = server.executed();  // before the reply, so a host that has it sees the count
	int delay_ms = 0;
	const std::string reply = applyFaults(full, delay_ms);
	sleepUnlessStopped(delay_ms);
	if (!stop_ && !reply.empty()) link_.write(reply);
}

bool DeviceEmulator::silent()
{
	std::lock_guard<std::mutex> lock(mutex_);
	return faults_.silent || faults_.silent_after_replies == 0;
}

std::string DeviceEmulator::applyFaults(std::string reply, int& delay_ms)
{
	std::lock_guard<std::mutex> lock(mutex_);
	delay_ms = faults_.reply_delay_ms;
	if (faults_.silent_after_replies > 0) --faults_.silent_after_replies;
	if (faults_.garbage_replies > 0)
	{
		--faults_.garbage_replies;
		return std::string("\x13\xff\x00 garbage \x80\x7f\n", 15);
	}
	if (faults_.drop_byte_replies > 0)
	{
		--faults_.drop_byte_replies;
		reply.erase(reply.size() / 2, 1);
	}
	std::bernoulli_distribution drop(faults_.drop_byte_probability);
	std::string kept;
	for (char c : reply)
		if (faults_.drop_byte_probability <= 0 || !drop(rng_)) kept += c;
	return kept;
}

void DeviceEmulator::sleepUnlessStopped(int ms) const
{
	const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
	while (!stop_ && std::chrono::steady_clock::now() < until)
		std::this_thread::sleep_for(std::chrono::milliseconds(std::min(ms, 5)));
}

}  // namespace mrolr::hw_serial
