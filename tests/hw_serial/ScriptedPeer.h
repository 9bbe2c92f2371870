#pragma once
// The device end of a memory pipe played from a script: for each request line it records the exact
// bytes and writes the scripted reply pieces, so tests can check the driver byte by byte.
#include <mrolr/hw_serial/MemoryTransport.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

class ScriptedPeer
{
 public:
	/** Reply pieces per request, written with @p gap_ms between pieces; an empty list answers
	 * nothing. Requests beyond the script are recorded and not answered. */
	ScriptedPeer(std::unique_ptr<mrolr::hw_serial::MemoryTransport> end,
	             std::vector<std::vector<std::string>> script, int gap_ms = 0)
	    : end_(std::move(end)), script_(std::move(script)), gap_ms_(gap_ms)
	{
		thread_ = std::thread([this] { run(); });
	}
	~ScriptedPeer()
	{
		stop_ = true;
		thread_.join();
	}
	/** Request lines received (with their '\n'), once at least @p n have arrived or after 2 s: the
	 * peer thread may still be reading the last one when the driver call returns. */
	std::vector<std::string> requests(size_t n = 0) const
	{
		const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
		for (;;)
		{
			{
				std::lock_guard<std::mutex> lock(mutex_);
				if (requests_.size() >= n || std::chrono::steady_clock::now() > until)
					return requests_;
			}
			std::this_thread::sleep_for(std::chrono::milliseconds(1));
		}
	}
	void close() { end_->close(); }

 private:
	void run()
	{
		std::string buffer;
		try
		{
			while (!stop_)
			{
				buffer += end_->read(10);
				for (size_t nl; (nl = buffer.find('\n')) != std::string::npos;)
				{
					size_t index = 0;
					{
						std::lock_guard<std::mutex> lock(mutex_);
						requests_.push_back(buffer.substr(0, nl + 1));
						index = requests_.size() - 1;
					}
					buffer.erase(0, nl + 1);
					answer(index);
				}
			}
		}
		catch (const mrolr::hw_serial::TransportClosed&)
		{
		}
	}
	void answer(size_t i)
	{
		if (i >= script_.size()) return;
		for (const auto& piece : script_[i])
		{
			std::this_thread::sleep_for(std::chrono::milliseconds(gap_ms_));
			end_->write(piece);
		}
	}

	std::unique_ptr<mrolr::hw_serial::MemoryTransport> end_;
	std::vector<std::vector<std::string>> script_;
	int gap_ms_;
	mutable std::mutex mutex_;
	std::vector<std::string> requests_;
	std::atomic<bool> stop_{false};
	std::thread thread_;
};
