// One device's request and replies over topics (DeviceLink.h).
#include "DeviceLink.h"

#include <chrono>
#include <thread>

namespace mrolr::ros
{
namespace
{
using Clock = std::chrono::steady_clock;

/** "limit: what" → {limit, what}; no kind → {failed, text}. */
DeviceFault parseFault(const std::string& text)
{
	const auto colon = text.find(": ");
	if (colon == std::string::npos) return {"failed", text};
	return {text.substr(0, colon), text.substr(colon + 2)};
}
}  // namespace

DeviceLink::DeviceLink(const ::ros::NodeHandle& nh, std::string device, int timeout_ms)
    : nh_(nh), device_(std::move(device)), timeout_ms_(timeout_ms)
{
}

void DeviceLink::faults(const std::string& topic)
{
	fault_ = reply<std_msgs::String>(topic);
	fault_index_ = replies_.size() - 1;
}

void DeviceLink::fail(const std::string& why) const
{
	throw hw::DeviceFailure(device_ + " over ROS: " + why);
}

std::string DeviceLink::silentTopics(const std::vector<size_t>& before) const
{
	std::string out;
	for (size_t i = 0; i < replies_.size(); ++i)
		if (replies_[i].count() == before[i])
		{
			out += (out.empty() ? "" : ", ") + replies_[i].topic;
			const auto node = replies_[i].publisher();
			if (!node.empty()) out += " (from " + node + ")";
		}
	return out;
}

void DeviceLink::awaitPeers(int wait_ms)
{
	const auto deadline = Clock::now() + std::chrono::milliseconds(wait_ms);
	for (;;)
	{
		std::string missing;
		for (const auto& c : commands_)
			if (c.getNumSubscribers() == 0 && missing.empty())
				missing = "nothing subscribes to " + c.getTopic();
		for (const auto& r : replies_)
			if (r.sub.getNumPublishers() == 0 && missing.empty())
				missing = "nothing publishes " + r.topic;
		if (missing.empty())
		{
			// a subscriber counts the lab's publisher a moment before the lab has taken its
			// connection header; what the lab sends in that moment would not reach it
			std::this_thread::sleep_for(std::chrono::milliseconds(200));
			return;
		}
		if (Clock::now() > deadline || !::ros::ok())
			fail(missing + " after " + std::to_string(wait_ms) +
			     " ms: is the lab node (mrolr-ros-lab) running under ROS_MASTER_URI=" +
			     ::ros::master::getURI() + "?");
		std::this_thread::sleep_for(std::chrono::milliseconds(10));
	}
}

std::optional<DeviceFault> DeviceLink::call(const std::function<void()>& publish,
                                            const std::string& what, int extra_ms)
{
	// what came for earlier calls (a grab's head/joint_states reaches the move link too) is
	// counted before this call's replies are waited for
	queue_.callAvailable(::ros::WallDuration(0));
	std::vector<size_t> before;
	for (const auto& r : replies_) before.push_back(r.count());
	publish();
	const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms_ + extra_ms);
	for (;;)
	{
		queue_.callAvailable(::ros::WallDuration(0.002));
		const bool fault_came = fault_ && fault_->count > before[fault_index_];
		if (fault_came && !fault_->msg->data.empty()) return parseFault(fault_->msg->data);
		bool all = true;
		for (size_t i = 0; i < replies_.size(); ++i) all &= replies_[i].count() > before[i];
		if (all) return std::nullopt;
		if (!::ros::ok()) fail(what + ": ROS shut down while waiting for the reply");
		for (const auto& r : replies_)
			if (r.sub.getNumPublishers() == 0)
				fail(what + ": no node publishes " + r.topic + " any more" +
				     (r.publisher().empty() ? "" : " (it was " + r.publisher() + ")"));
		if (Clock::now() > deadline)
			fail(what + ": no reply on " + silentTopics(before) + " within " +
			     std::to_string(timeout_ms_ + extra_ms) + " ms (is that node still running?)");
	}
}

}  // namespace mrolr::ros
