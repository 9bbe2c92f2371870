// The world side of the devices over topics (DeviceServer.h).
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceServer.h>
#include <mrolr/ros/DeviceTopics.h>

#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>

namespace mrolr::ros
{
namespace
{
constexpr double kMPerMm = 1e-3;
constexpr double kRadPerDeg = M_PI / 180.0;

/** Runs @p fn; what it throws becomes the fault text ("KIND: what"), "" when it went well. */
template <typename Fn>
std::string faultOf(Fn fn)
{
	try
	{
		fn();
		return "";
	}
	catch (const geometry::FixationError& e)
	{
		return topics::kLimit + ": " + e.what();
	}
	catch (const std::out_of_range& e)
	{
		return topics::kLimit + ": " + e.what();
	}
	catch (const hw::ArmBlocked& e)
	{
		return topics::kBlocked + ": " + e.what();
	}
	catch (const std::logic_error& e)
	{
		return topics::kRefused + ": " + e.what();
	}
	catch (const std::exception& e)
	{
		return topics::kFailed + ": " + e.what();
	}
}

std_msgs::String text(const std::string& s)
{
	std_msgs::String m;
	m.data = s;
	return m;
}

std_msgs::Float64 number(double v)
{
	std_msgs::Float64 m;
	m.data = v;
	return m;
}

/** The encoders and the dead reckoning as joints (DeviceTopics.h). */
sensor_msgs::JointState baseJoints(const hw::Odometry& o)
{
	sensor_msgs::JointState j;
	j.header.stamp = toRosTime(o.time_s);
	j.name.assign(topics::kWheelJoints.begin(), topics::kWheelJoints.end());
	j.name.insert(j.name.end(), topics::kOdomJoints.begin(), topics::kOdomJoints.end());
	// REP 103 x = the thesis's z, y = its x (ros/Conversions.h planarPose); the yaw as the base
	// turned, not wrapped
	j.position = {double(o.ticks_right), double(o.ticks_left), o.xv_zxphi[0], o.xv_zxphi[1],
	              o.xv_zxphi[2]};
	return j;
}

std_msgs::Bool flag(bool b)
{
	std_msgs::Bool m;
	m.data = b;
	return m;
}

/** The point of a command, or null for a state request; throws std::invalid_argument naming
 * what does not fit the device's joints. */
const trajectory_msgs::JointTrajectoryPoint* pointOf(const trajectory_msgs::JointTrajectory& m,
                                                     size_t joints, bool velocities)
{
	if (m.points.empty()) return nullptr;
	if (m.points.size() != 1)
		throw std::invalid_argument("a command holds one trajectory point, not " +
		                            std::to_string(m.points.size()));
	const auto& v = velocities ? m.points[0].velocities : m.points[0].positions;
	if (v.size() != joints)
		throw std::invalid_argument("expected " + std::to_string(joints) + " joint values, got " +
		                            std::to_string(v.size()));
	return &m.points[0];
}
}  // namespace

struct DeviceServer::Impl
{
	ServedDevices d;
	size_t commands = 0;
	std::function<void(double)>* after_step;
	std::function<void(double)>* after_grab;
	std::vector<::ros::Subscriber> subs;
	::ros::Publisher odom, base_joints, bumper, base_clock, base_fault, tf;
	::ros::Publisher head_joints, settle, head_fault, left, right, stereo_clock, stereo_fault;
	::ros::Publisher arm_joints, closed, docked, arm_fault;

	Impl(::ros::NodeHandle& nh, const ServedDevices& devices, std::function<void(double)>* step,
	     std::function<void(double)>* grabbed)
	    : d(devices), after_step(step), after_grab(grabbed)
	{
		if (d.base) serveBase(nh);
		if (d.head) serveHead(nh);
		if (d.arm) serveArm(nh);
	}

	template <typename M, typename Fn>
	void on(::ros::NodeHandle& nh, const std::string& topic, Fn fn)
	{
		subs.push_back(nh.subscribe<M>(topic, 8,
		                               boost::function<void(const typename M::ConstPtr&)>(
		                                   [this, fn](const typename M::ConstPtr& m)
		                                   {
			                                   ++commands;
			                                   fn(*m);
		                                   }),
		                               ::ros::VoidConstPtr(),
		                               ::ros::TransportHints().tcpNoDelay()));
	}

	void serveBase(::ros::NodeHandle& nh)
	{
		odom = nh.advertise<nav_msgs::Odometry>(topics::kOdom, topics::kPublisherQueue);
		base_joints =
		    nh.advertise<sensor_msgs::JointState>(topics::kBaseJoints, topics::kPublisherQueue);
		bumper = nh.advertise<std_msgs::Bool>(topics::kBumper, topics::kPublisherQueue);
		base_clock = nh.advertise<std_msgs::Float64>(topics::kBaseClock, topics::kPublisherQueue);
		base_fault = nh.advertise<std_msgs::String>(topics::kBaseFault, topics::kPublisherQueue);
		tf = nh.advertise<tf2_msgs::TFMessage>("/tf", topics::kPublisherQueue);
		on<trajectory_msgs::JointTrajectory>(nh, topics::kBaseCommand,
		                                     [this](const auto& m) { baseCommand(m); });
	}

	void baseCommand(const trajectory_msgs::JointTrajectory& m)
	{
		bool stepped = false;
		const auto fault = faultOf(
		    [&]
		    {
			    if (const auto* p = pointOf(m, 2, true))
			    {
				    const double dt_s =
				        p->effort.size() == 1 ? p->effort[0] : secondsOf(p->time_from_start);
				    d.base->step({p->velocities[0], p->velocities[1], dt_s});
				    stepped = true;
			    }
		    });
		if (fault.empty())
		{
			const auto o = d.base->odometry();
			odom.publish(toOdometryMsg(o.xv_zxphi, o.time_s));
			base_joints.publish(baseJoints(o));
			bumper.publish(flag(o.bumper));
			base_clock.publish(number(o.time_s));
			tf2_msgs::TFMessage t;
			t.transforms.push_back(
			    toTransformMsg(planarPose(o.xv_zxphi), "odom", "base_link", o.time_s));
			tf.publish(t);
			if (stepped && *after_step) (*after_step)(o.time_s);
		}
		base_fault.publish(text(fault));
	}

	void serveHead(::ros::NodeHandle& nh)
	{
		head_joints =
		    nh.advertise<sensor_msgs::JointState>(topics::kHeadJoints, topics::kPublisherQueue);
		settle = nh.advertise<std_msgs::Float64>(topics::kHeadSettle, topics::kPublisherQueue);
		head_fault = nh.advertise<std_msgs::String>(topics::kHeadFault, topics::kPublisherQueue);
		left = nh.advertise<sensor_msgs::Image>(topics::kLeftImage, topics::kPublisherQueue);
		right = nh.advertise<sensor_msgs::Image>(topics::kRightImage, topics::kPublisherQueue);
		stereo_clock =
		    nh.advertise<std_msgs::Float64>(topics::kStereoClock, topics::kPublisherQueue);
		stereo_fault =
		    nh.advertise<std_msgs::String>(topics::kStereoFault, topics::kPublisherQueue);
		on<trajectory_msgs::JointTrajectory>(nh, topics::kHeadCommand,
		                                     [this](const auto& m) { headCommand(m); });
		on<std_msgs::Empty>(nh, topics::kStereoTrigger, [this](const auto&) { grab(); });
	}

	void publishAngles(const geometry::HeadAngles& a, double time_s)
	{
		head_joints.publish(
		    headJointsMsg(Eigen::Vector4d(a.pan, a.tilt, a.verg_left, a.verg_right), time_s));
	}

	double baseTime() const { return d.base ? d.base->odometry().time_s : 0.0; }

	void headCommand(const trajectory_msgs::JointTrajectory& m)
	{
		double settle_s = 0;
		const auto fault = faultOf(
		    [&]
		    {
			    if (const auto* p = pointOf(m, 4, false))
				    settle_s = d.head->moveTo(
				        {p->positions[0], p->positions[1], p->positions[2], p->positions[3]});
		    });
		if (fault.empty())
		{
			publishAngles(d.head->angles(), baseTime());
			settle.publish(number(settle_s));
		}
		head_fault.publish(text(fault));
	}

	void grab()
	{
		hw::StereoImages pair;
		auto fault = faultOf([&] { pair = d.head->grab(); });
		if (fault.empty())
			fault = faultOf(
			    [&]
			    {
				    left.publish(toImageMsg(pair.left, pair.time_s, "left_camera"));
				    right.publish(toImageMsg(pair.right, pair.time_s, "right_camera"));
				    publishAngles(pair.angles, pair.time_s);
				    stereo_clock.publish(number(pair.time_s));
				    if (*after_grab) (*after_grab)(pair.time_s);
			    });
		stereo_fault.publish(text(fault));
	}

	void serveArm(::ros::NodeHandle& nh)
	{
		arm_joints =
		    nh.advertise<sensor_msgs::JointState>(topics::kArmJoints, topics::kPublisherQueue);
		closed = nh.advertise<std_msgs::Bool>(topics::kGripperClosed, topics::kPublisherQueue);
		docked = nh.advertise<std_msgs::Bool>(topics::kArmDocked, topics::kPublisherQueue);
		arm_fault = nh.advertise<std_msgs::String>(topics::kArmFault, topics::kPublisherQueue);
		on<trajectory_msgs::JointTrajectory>(nh, topics::kArmCommand,
		                                     [this](const auto& m) { armCommand(m); });
		on<std_msgs::Bool>(nh, topics::kGripperCommand,
		                   [this](const auto& m)
		                   { armReply(faultOf([&] { d.arm->setGripper(m.data); })); });
		on<std_msgs::Bool>(nh, topics::kDockCommand,
		                   [this](const auto& m)
		                   { armReply(faultOf([&] { d.arm->dock(m.data); })); });
	}

	void armCommand(const trajectory_msgs::JointTrajectory& m)
	{
		armReply(faultOf(
		    [&]
		    {
			    const auto* p = pointOf(m, 7, false);
			    if (!p) return;
			    hw::ArmJoints j;
			    j[0] = p->positions[0] / kMPerMm;
			    for (size_t i = 1; i < 7; ++i) j[i] = p->positions[i] / kRadPerDeg;
			    d.arm->moveTo(j);
		    }));
	}

	/** The arm's whole state, then the fault (a faulty command gets the fault only). */
	void armReply(const std::string& fault)
	{
		if (fault.empty())
		{
			const auto j = d.arm->joints();
			sensor_msgs::JointState s;
			s.header.stamp = toRosTime(baseTime());
			s.name.assign(topics::kArmJointNames.begin(), topics::kArmJointNames.end());
			s.name.push_back(topics::kGripperJoint);
			s.position.push_back(j[0] * kMPerMm);
			for (size_t i = 1; i < 7; ++i) s.position.push_back(j[i] * kRadPerDeg);
			s.position.push_back(d.arm->gripperWidthMm() * kMPerMm);
			arm_joints.publish(s);
			closed.publish(flag(d.arm->gripperClosed()));
			docked.publish(flag(d.arm->docked()));
		}
		arm_fault.publish(text(fault));
	}
};

DeviceServer::DeviceServer(::ros::NodeHandle& nh, const ServedDevices& d)
    : impl_(std::make_unique<Impl>(nh, d, &after_step, &after_grab))
{
}

DeviceServer::~DeviceServer() = default;

size_t DeviceServer::commands() const
{
	return impl_->commands;
}

}  // namespace mrolr::ros
