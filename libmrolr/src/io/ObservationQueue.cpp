// The rawlog writer thread behind a mission's recording.
#include <mrolr/io/ObservationQueue.h>

#include <algorithm>
#include <chrono>
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
	const auto t0 = std::chrono::steady_clock::now();
	changed_.wait(lock, [this] { return queue_.size() < capacity_ || !failure_.empty(); });
	wait_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	rethrowFailure();
	queue_.push_back(std::move(write));
	max_queued_ = std::max(max_queued_, queue_.size());
	changed_.notify_all();
}

void ObservationQueue::flush()
{
	std::unique_lock lock(m_);
	changed_.wait(lock, [this] { return (queue_.empty() && !busy_) || !failure_.empty(); });
	rethrowFailure();
}

ObservationQueue::Stats ObservationQueue::stats()
{
	std::unique_lock lock(m_);
	return {log_.count(), log_.images(), log_.bytes(), log_.imageBytes(), write_s_, wait_s_,
	        max_queued_};
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
		const auto t0 = std::chrono::steady_clock::now();
		try
		{
			if (!failed_before) next(log_);  // after a failure nothing more is written
		}
		catch (const std::exception& e)
		{
			failed = e.what();
		}
		const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		lock.lock();
		write_s_ += took;
		busy_ = false;
		if (!failed.empty() && failure_.empty()) failure_ = failed;
		changed_.notify_all();
	}
}

}  // namespace mrolr::io
