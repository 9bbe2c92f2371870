// The rawlog writer thread behind a mission's recording.
#include <mrolr/io/ObservationQueue.h>

#include <algorithm>
#include <stdexcept>

namespace mrolr::io
{
ObservationQueue::ObservationQueue(const std::string& path, size_t capacity)
    : path_(path), log_(path), capacity_(std::max<size_t>(1, capacity))
{
	writer_ = std::thread([this] { run(); });
}

ObservationQueue::~ObservationQueue()
{
	{
		std::unique_lock lock(m_);
		stopping_ = true;
	}
	changed_.notify_all();
	writer_.join();  // run() writes everything still queued first
}

void ObservationQueue::rethrowFailure()
{
	if (!failure_.empty()) throw std::runtime_error("recording " + path_ + ": " + failure_);
}

void ObservationQueue::post(Write write)
{
	std::unique_lock lock(m_);
	changed_.wait(lock, [this] { return queue_.size() < capacity_ || !failure_.empty(); });
	rethrowFailure();
	queue_.push_back(std::move(write));
	changed_.notify_all();
}

void ObservationQueue::flush()
{
	std::unique_lock lock(m_);
	changed_.wait(lock, [this] { return (queue_.empty() && !busy_) || !failure_.empty(); });
	rethrowFailure();
}

void ObservationQueue::run()
{
	std::unique_lock lock(m_);
	for (;;)
	{
		changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
		if (queue_.empty()) return;  // stopping, and everything is written
		Write next = std::move(queue_.front());
		queue_.pop_front();
		busy_ = true;
		const bool failed_before = !failure_.empty();
		lock.unlock();
		std::string failed;
		try
		{
			if (!failed_before) next(log_);  // after a failure nothing more is written
		}
		catch (const std::exception& e)
		{
			failed = e.what();
		}
		lock.lock();
		busy_ = false;
		if (!failed.empty() && failure_.empty()) failure_ = failed;
		changed_.notify_all();
	}
}

}  // namespace mrolr::io
