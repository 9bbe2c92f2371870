#include <mrolr/hw_serial/MemoryTransport.h>

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace mrolr::hw_serial
{
struct MemoryTransport::Shared
{
	std::mutex mutex;
	std::condition_variable cv;
	std::string inbox[2];  ///< bytes waiting for side 0 and side 1
	bool closed = false;
};

void MemoryTransport::write(const std::string& bytes)
{
	std::lock_guard<std::mutex> lock(shared_->mutex);
	if (shared_->closed) throw TransportClosed("memory: the pipe is closed");
	shared_->inbox[1 - side_] += bytes;
	shared_->cv.notify_all();
}

std::string MemoryTransport::read(int timeout_ms)
{
	std::unique_lock<std::mutex> lock(shared_->mutex);
	auto& box = shared_->inbox[side_];
	shared_->cv.wait_for(lock, std::chrono::milliseconds(timeout_ms),
	                     [&] { return !box.empty() || shared_->closed; });
	if (shared_->closed) throw TransportClosed("memory: the pipe is closed");
	std::string out;
	out.swap(box);
	return out;
}

void MemoryTransport::close()
{
	std::lock_guard<std::mutex> lock(shared_->mutex);
	shared_->closed = true;
	shared_->cv.notify_all();
}

std::pair<std::unique_ptr<MemoryTransport>, std::unique_ptr<MemoryTransport>> makeMemoryPipe()
{
	auto shared = std::make_shared<MemoryTransport::Shared>();
	return {std::make_unique<MemoryTransport>(shared, 0),
	        std::make_unique<MemoryTransport>(shared, 1)};
}

}  // namespace mrolr::hw_serial
