// Round-trip time of one request (ODO? on a recording base) through the serial stack: client,
// framing with CRC-32, device emulator thread; over the in-memory pipe and over a real
// pseudo-terminal opened with mrpt::comms::CSerialPort (docs/serial.md).
#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/hw_serial/MemoryTransport.h>
#include <mrolr/hw_serial/SerialClient.h>
#include <mrolr/hw_serial/SerialPortTransport.h>

#include <benchmark/benchmark.h>

using namespace mrolr;

namespace
{
struct IdleBase : hw::BaseDevice
{
	hw::Odometry odo;
	void step(const base::WheelControl&) override {}
	hw::Odometry odometry() const override { return odo; }
};

hw_serial::LinkOptions link()
{
	hw_serial::LinkOptions o;
	o.device = "bench";
	o.timeout_ms = 1000;
	return o;
}

void roundTrips(benchmark::State& state, hw_serial::SerialClient& client)
{
	for (auto _ : state) benchmark::DoNotOptimize(client.call("ODO?", {}));
	state.SetItemsProcessed(state.iterations());
}
}  // namespace

static void BM_RoundTripMemoryPipe(benchmark::State& state)
{
	IdleBase base;
	hw_serial::BaseHandler handler(base);
	auto [host, dev] = hw_serial::makeMemoryPipe();
	hw_serial::DeviceEmulator emulator(*dev, handler);
	hw_serial::SerialClient client(std::move(host), link());
	roundTrips(state, client);
}
BENCHMARK(BM_RoundTripMemoryPipe)->Unit(benchmark::kMicrosecond)->UseRealTime();

static void BM_RoundTripPseudoTerminal(benchmark::State& state)
{
	IdleBase base;
	hw_serial::BaseHandler handler(base);
	hw_serial::PtyEmulator pty(handler);
	hw_serial::SerialClient client(std::make_unique<hw_serial::SerialPortTransport>(pty.slavePath(), 115200),
	                        link());
	roundTrips(state, client);
}
BENCHMARK(BM_RoundTripPseudoTerminal)->Unit(benchmark::kMicrosecond)->UseRealTime();

BENCHMARK_MAIN();
