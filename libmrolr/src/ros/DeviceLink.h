#pragma once
// One device's request and replies over topics, on the robot's side (DeviceTopics.h): a command
// is published, then the link waits for one new message on each of the device's reply topics, or
// a fault. Single-threaded: the replies are delivered on the link's own callback queue, which only
// call() spins, so a device call is as deterministic as one in process.
#include <mrolr/hw/Devices.h>
#include <mrolr/ros/DeviceTopics.h>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::ros
{
/** A topic's last message and how many have come. */
template <typename M>
struct Latest
{
	typename M::ConstPtr msg;
	size_t count = 0;
	std::string publisher;  ///< the node that sent the last one
};

/** A fault the lab reported on `<device>/fault` ("KIND: what"). */
struct DeviceFault
{
	std::string kind, what;
};

class DeviceLink
{
 public:
	/** @p device names the device in errors ("device.base"); @p timeout_ms is how long a reply
	 * may take beyond the command's own duration. */
	DeviceLink(const ::ros::NodeHandle& nh, std::string device, int timeout_ms);
	DeviceLink(const DeviceLink&) = delete;
	DeviceLink& operator=(const DeviceLink&) = delete;

	/** Subscribes to a reply topic; every call() then waits for one new message on it. */
	template <typename M>
	std::shared_ptr<Latest<M>> reply(const std::string& topic);
	/** The device's fault topic (waited for too). */
	void faults(const std::string& topic);
	template <typename M>
	::ros::Publisher command(const std::string& topic)
	{
		auto p = nh_.advertise<M>(topic, topics::kPublisherQueue);
		commands_.push_back(p);
		return p;
	}

	/** Waits until every command topic has a subscriber and every reply topic a publisher (the lab
	 * is up); throws hw::DeviceFailure naming the first missing one after @p wait_ms. */
	void awaitPeers(int wait_ms);
	/** Runs @p publish, then waits for the replies (@p extra_ms on top of the timeout). Returns the
	 * fault when the lab reported one; throws hw::DeviceFailure naming the device, the topics still
	 * silent and the node that served them when no reply comes, or when that node is gone. */
	std::optional<DeviceFault> call(const std::function<void()>& publish, const std::string& what,
	                                int extra_ms = 0);
	const std::string& device() const { return device_; }

 private:
	struct Reply
	{
		std::string topic;
		::ros::Subscriber sub;
		std::function<size_t()> count;
		std::function<std::string()> publisher;
	};
	[[noreturn]] void fail(const std::string& why) const;
	std::string silentTopics(const std::vector<size_t>& before) const;

	::ros::NodeHandle nh_;
	::ros::CallbackQueue queue_;
	std::string device_;
	int timeout_ms_;
	std::vector<Reply> replies_;
	std::vector<::ros::Publisher> commands_;
	std::shared_ptr<Latest<std_msgs::String>> fault_;
	size_t fault_index_ = 0;
};

template <typename M>
std::shared_ptr<Latest<M>> DeviceLink::reply(const std::string& topic)
{
	auto latest = std::make_shared<Latest<M>>();
	::ros::SubscribeOptions so;
	so.template initByFullCallbackType<const ::ros::MessageEvent<M const>&>(
	    topic, 8,
	    [latest](const ::ros::MessageEvent<M const>& e)
	    {
		    latest->msg = e.getMessage();
		    latest->publisher = e.getPublisherName();
		    ++latest->count;
	    });
	so.callback_queue = &queue_;
	so.transport_hints = ::ros::TransportHints().tcpNoDelay();
	replies_.push_back({nh_.resolveName(topic), nh_.subscribe(so),
	                    [latest] { return latest->count; },
	                    [latest] { return latest->publisher; }});
	return latest;
}

}  // namespace mrolr::ros
