#pragma once
// Shared by the camera tests: noise images, pixel comparison, and a TCP peer on 127.0.0.1 that
// plays a script on each connection instead of serving pairs (garbage, silence, wrong replies).
#include <mrolr/hw/Devices.h>
#include <mrolr/hw_serial/SocketIo.h>

#include <mrpt/comms/CClientTCPSocket.h>
#include <mrpt/comms/CServerTCPSocket.h>

#include <atomic>
#include <cstring>
#include <functional>
#include <random>
#include <thread>

namespace camtest
{
/** An 8-bit grey image of uniform random pixels. */
inline mrpt::img::CImage noiseImage(unsigned w, unsigned h, unsigned seed)
{
	std::mt19937 rng(seed);
	mrpt::img::CImage im(w, h, mrpt::img::CH_GRAY);
	for (unsigned y = 0; y < h; ++y)
		for (unsigned x = 0; x < w; ++x) im.ptrLine<uint8_t>(y)[x] = uint8_t(rng());
	return im;
}

inline mrolr::hw::StereoImages noisePair(unsigned w, unsigned h, unsigned seed)
{
	mrolr::hw::StereoImages p;
	p.left = noiseImage(w, h, seed);
	p.right = noiseImage(w, h, seed + 1000);
	p.time_s = 12.345678901234567 + seed;
	p.angles = {0.1234567890123 * seed, -0.2, 1e-9, -0.30000000000000004};
	return p;
}

/** Same size, both grey, identical pixels row by row. */
inline bool sameGreyPixels(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) return false;
	if (a.isColor() || b.isColor()) return false;
	for (unsigned y = 0; y < a.getHeight(); ++y)
		if (std::memcmp(a.ptrLine<uint8_t>(y), b.ptrLine<uint8_t>(y), a.getWidth()) != 0)
			return false;
	return true;
}

/** Listens on a free loopback port and runs @p script on every accepted connection, from its
 * own thread, until destroyed (the script gets the stop flag to end its waits). */
class ScriptedCameraPeer
{
 public:
	using Script = std::function<void(mrpt::comms::CClientTCPSocket&, const std::atomic<bool>&)>;

	explicit ScriptedCameraPeer(Script script)
	    : script_(std::move(script)),
	      port_(mrolr::hw_serial::freeLoopbackPort()),
	      listener_(port_, "127.0.0.1", 4, mrpt::system::LVL_ERROR)
	{
		thread_ = std::thread(
		    [this]
		    {
			    while (!stop_)
				    if (auto c = listener_.accept(20)) script_(*c, stop_);
		    });
	}
	~ScriptedCameraPeer()
	{
		stop_ = true;
		thread_.join();
	}
	std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

 private:
	Script script_;
	uint16_t port_;
	mrpt::comms::CServerTCPSocket listener_;
	std::atomic<bool> stop_{false};
	std::thread thread_;
};

/** Reads one 12-byte request (false when none comes within 2 s). */
inline bool readRequest(mrpt::comms::CClientTCPSocket& c, const std::atomic<bool>& stop,
                        std::string& request)
{
	return mrolr::hw_serial::readExact(c, 12, request, mrolr::hw_serial::deadlineIn(2000), &stop) ==
	       mrolr::hw_serial::SocketIoStatus::Done;
}

/** Waits until the peer hangs up or the stop flag is raised (a device that never answers). */
inline void holdSilently(mrpt::comms::CClientTCPSocket& c, const std::atomic<bool>& stop)
{
	std::string sink;
	while (mrolr::hw_serial::readExact(c, 1, sink, mrolr::hw_serial::kNoSocketDeadline, &stop) ==
	       mrolr::hw_serial::SocketIoStatus::Done)
	{
	}
}

}  // namespace camtest
