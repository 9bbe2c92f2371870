// One 640x480 stereo pair through the camera socket: request, grab (a fixed pair), MRPT
// serialization, loopback TCP, deserialization; and the encoding and decoding alone, without
// sockets (docs/serial.md "The camera socket").
#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/hw_serial/CameraWire.h>

#include <benchmark/benchmark.h>

#include <random>

using namespace mrolr;

namespace
{
mrpt::img::CImage noise(unsigned seed)
{
	std::mt19937 rng(seed);
	mrpt::img::CImage im(640, 480, mrpt::img::CH_GRAY);
	for (unsigned y = 0; y < 480; ++y)
		for (unsigned x = 0; x < 640; ++x) im.ptrLine<uint8_t>(y)[x] = uint8_t(rng());
	return im;
}

hw::StereoImages pair640x480()
{
	hw::StereoImages p;
	p.left = noise(1);
	p.right = noise(2);
	p.time_s = 1.5;
	return p;
}
}  // namespace

static void BM_CameraSocketPairRoundTrip(benchmark::State& state)
{
	const auto pair = pair640x480();
	hw_serial::CameraServer server([&] { return pair; });
	hw_serial::CameraSocketClient client(server.address(), 5000);
	for (auto _ : state) benchmark::DoNotOptimize(client.grab());
	state.SetBytesProcessed(int64_t(state.iterations()) * 2 * 640 * 480);
}
BENCHMARK(BM_CameraSocketPairRoundTrip)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_CameraPairEncodeDecode(benchmark::State& state)
{
	const auto pair = pair640x480();
	for (auto _ : state)
	{
		const std::string frame = hw_serial::encodeCameraImages(1, pair);
		benchmark::DoNotOptimize(
		    hw_serial::decodeCameraImages(std::string_view(frame).substr(hw_serial::kCameraHeaderBytes)));
	}
	state.SetBytesProcessed(int64_t(state.iterations()) * 2 * 640 * 480);
}
BENCHMARK(BM_CameraPairEncodeDecode)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
