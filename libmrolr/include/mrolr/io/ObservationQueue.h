#pragma once
/** An ObservationLogWriter fed from a queue by a writer thread, so that encoding images and
 * writing records overlap with the work of the thread that posts them (the robot's). Posted
 * writes run in the order they were posted; a full queue makes post() wait. A write that failed
 * is thrown again by the next post() or flush(), naming the file. The destructor writes what is
 * still queued. What a killed process had only posted is lost; what the writer wrote reads back
 * whole (ObservationLog.h). */
#include <mrolr/io/ObservationLog.h>

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace mrolr::io
{
class ObservationQueue
{
 public:
	using Write = std::function<void(ObservationLogWriter&)>;
	/** Opens @p path (ObservationLogWriter; throws as it does) and starts the writer thread;
	 * at most @p capacity writes wait in the queue. */
	explicit ObservationQueue(const std::string& path, size_t capacity = 64);
	~ObservationQueue();
	ObservationQueue(const ObservationQueue&) = delete;
	ObservationQueue& operator=(const ObservationQueue&) = delete;
	/** Queues @p write (throws std::runtime_error when an earlier write failed). */
	void post(Write write);
	/** Waits until every posted write is done (throws when one failed). */
	void flush();
	const std::string& path() const { return path_; }

	/** What the writer did, for the report (call after flush()). */
	struct Stats
	{
		size_t records = 0, images = 0;
		uint64_t bytes = 0, image_bytes = 0;
		double write_s = 0;  ///< wall seconds the writer thread spent writing
		double wait_s = 0;   ///< wall seconds post() waited for room: the poster's cost
		size_t max_queued = 0;
	};
	Stats stats();

 private:
	void run();
	void rethrowFailure();

	std::string path_;
	ObservationLogWriter log_;
	size_t capacity_;
	std::deque<Write> queue_;
	bool busy_ = false, stopping_ = false;
	std::string failure_;
	double write_s_ = 0, wait_s_ = 0;
	size_t max_queued_ = 0;
	std::mutex m_;
	std::condition_variable changed_;
	std::thread writer_;
};

}  // namespace mrolr::io
