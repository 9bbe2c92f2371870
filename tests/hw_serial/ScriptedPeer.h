#pragma once
// The device end of a memory pipe played from a script: for each request line it records the exact
// bytes and writes the scripted reply pieces, so tests can check the driver byte by byte.
#include <mrolr/hw_serial/MemoryTransport.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

class ScriptedPeer
{
 public:
	/** Reply pieces per request, written with @p gap_ms between pieces; an empty list answers
	 * nothing. Requests beyond the script are recorded and not answered. */
	ScriptedPeer(std::unique_ptr<mrolr::hw::MemoryTransport> end,
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
	/** Request lines received so far (with their '\n'); read after the driver call returned. */
	const std::vector<std::string>& requests() const { return requests_; }
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
					requests_.push_back(buffer.substr(0, nl + 1));
					buffer.erase(0, nl + 1);
					answer(requests_.size() - 1);
				}
			}
		}
		catch (const mrolr::hw::TransportClosed&)
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

	std::unique_ptr<mrolr::hw::MemoryTransport> end_;
	std::vector<std::vector<std::string>> script_;
	int gap_ms_;
	std::vector<std::string> requests_;
	std::atomic<bool> stop_{false};
	std::thread thread_;
};
