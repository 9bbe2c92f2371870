// mrolr-ros-bag: a mission's topics into a bag (RosBagApp.h).
#include <mrolr/apps/RosBagApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/ros/DeviceTopics.h>
#include <mrolr/ros/Node.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <visualization_msgs/MarkerArray.h>

#include <ostream>

namespace mrolr::apps
{
void RosBagApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-ros-bag: record a mission's topics into a bag (docs/ros.md)", ' ',
	                   "1");
	TCLAP::ValueArg<std::string> out("", "out", "the bag to write (overwritten)", true, "",
	                                 "OUT.bag", cmd);
	TCLAP::SwitchArg raw("", "no-compression", "write uncompressed chunks", cmd);
	TCLAP::ValueArg<int> wait("", "master-timeout-ms", "wait this long for the ROS master", false,
	                          master_timeout_ms, "N", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	bag_path = out.getValue();
	compress = !raw.getValue();
	master_timeout_ms = wait.getValue();
}

namespace
{
template <typename M>
::ros::Time stampOf(const M& m)
{
	if constexpr (::ros::message_traits::HasHeader<M>::value)
		return m.header.stamp;
	else if constexpr (std::is_same_v<M, tf2_msgs::TFMessage>)
		return m.transforms.empty() ? ::ros::Time() : m.transforms.front().header.stamp;
	else if constexpr (std::is_same_v<M, visualization_msgs::MarkerArray>)
		return m.markers.empty() ? ::ros::Time() : m.markers.front().header.stamp;
	return ::ros::Time();
}

class Recorder
{
 public:
	Recorder(::ros::NodeHandle& nh, rosbag::Bag& bag, std::map<std::string, size_t>& counts)
	    : nh_(nh), bag_(bag), counts_(counts)
	{
	}
	template <typename M>
	void record(const std::string& topic)
	{
		const std::string name = nh_.resolveName(topic);
		subs_.push_back(nh_.subscribe<M>(topic, ros::topics::kRecorderQueue,
		                                 boost::function<void(const typename M::ConstPtr&)>(
		                                     [this, name](const typename M::ConstPtr& m)
		                                     {
			                                     ::ros::Time t = stampOf(*m);
			                                     if (t.isZero()) t = ::ros::Time::now();
			                                     bag_.write(name, t, *m);
			                                     ++counts_[name];
		                                     })));
	}

 private:
	::ros::NodeHandle& nh_;
	rosbag::Bag& bag_;
	std::map<std::string, size_t>& counts_;
	std::vector<::ros::Subscriber> subs_;
};

void recordAll(Recorder& r)
{
	namespace t = ros::topics;
	for (const auto& topic : {t::kLeftImage, t::kRightImage}) r.record<sensor_msgs::Image>(topic);
	for (const auto& topic : {t::kLeftInfo, t::kRightInfo})
		r.record<sensor_msgs::CameraInfo>(topic);
	r.record<nav_msgs::Odometry>(t::kOdom);
	for (const auto& topic : {t::kBaseJoints, t::kHeadJoints, t::kArmJoints})
		r.record<sensor_msgs::JointState>(topic);
	for (const auto& topic :
	     {t::kBumper, t::kGripperClosed, t::kArmDocked, t::kGripperCommand, t::kDockCommand})
		r.record<std_msgs::Bool>(topic);
	for (const auto& topic : {t::kBaseCommand, t::kHeadCommand, t::kArmCommand})
		r.record<trajectory_msgs::JointTrajectory>(topic);
	for (const auto& topic : {t::kHeadSettle, t::kBaseClock, t::kStereoClock})
		r.record<std_msgs::Float64>(topic);
	for (const auto& topic :
	     {t::kBaseFault, t::kHeadFault, t::kStereoFault, t::kArmFault, t::kStage})
		r.record<std_msgs::String>(topic);
	r.record<std_msgs::Empty>(t::kStereoTrigger);
	r.record<tf2_msgs::TFMessage>("/tf");
	r.record<geometry_msgs::PoseWithCovarianceStamped>(t::kEstimate);
	r.record<geometry_msgs::PoseStamped>(t::kObjectPose);
	r.record<nav_msgs::Path>(t::kPath);
	r.record<visualization_msgs::MarkerArray>(t::kMap);
	r.record<geometry_msgs::PoseStamped>(t::kTruthPose);
}
}  // namespace

int RosBagApp::run(std::ostream& out)
{
	if (help_shown) return 0;
	rosbag::Bag bag;
	try
	{
		bag.open(bag_path, rosbag::bagmode::Write);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error("cannot write the bag " + bag_path + ": " + e.what());
	}
	if (compress) bag.setCompression(rosbag::compression::LZ4);
	ros::waitForMaster(master_timeout_ms);
	::ros::NodeHandle nh;
	Recorder recorder(nh, bag, counts);
	recordAll(recorder);
	out << "mrolr-ros-bag: recording into " << bag_path << " from " << ::ros::master::getURI()
	    << std::endl;
	::ros::spin();
	bag.close();
	size_t total = 0;
	for (const auto& [topic, n] : counts) total += n;
	out << "mrolr-ros-bag: " << total << " messages on " << counts.size() << " topics in "
	    << bag_path << "\n";
	for (const auto& [topic, n] : counts) out << "  " << topic << " " << n << "\n";
	return 0;
}

}  // namespace mrolr::apps
