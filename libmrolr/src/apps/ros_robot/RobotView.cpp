// What mrolr-ros-robot publishes of its own beliefs (RobotView.h).
#include "RobotView.h"

#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceTopics.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>

#include <Eigen/Eigenvalues>

namespace mrolr::apps
{
namespace
{
constexpr double kChi2_3dof_95 = 7.815;  ///< the 95 % quantile of χ² with 3 degrees of freedom
constexpr size_t kPathEverySteps = 10;   ///< mrolr/path is republished after this many estimates

/** A pose in thesis axes (W) as one in `world`'s REP 103 axes (geometry/Frames.h). */
Eigen::Isometry3d toRosAxes(const Eigen::Isometry3d& T_thesis)
{
	Eigen::Isometry3d T;
	T.matrix() = geometry::poseToMrpt(T_thesis)
	                 .getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>()
	                 .asEigen();
	return T;
}

void publishTf(::ros::Publisher& tf, const geometry_msgs::TransformStamped& t)
{
	tf2_msgs::TFMessage m;
	m.transforms.push_back(t);
	tf.publish(m);
}

visualization_msgs::Marker marker(const std::string& ns, int id, int type, double time_s)
{
	visualization_msgs::Marker m;
	m.header.frame_id = "world";
	m.header.stamp = ros::toRosTime(time_s);
	m.ns = ns;
	m.id = id;
	m.type = type;
	m.action = visualization_msgs::Marker::ADD;
	m.pose.orientation.w = 1;
	return m;
}
}  // namespace

visualization_msgs::MarkerArray mapMarkers(const std::vector<mission::MappedLandmark>& map,
                                           double time_s)
{
	visualization_msgs::MarkerArray out;
	const Eigen::Matrix3d P_axes = geometry::R_mrptFromThesis();
	int id = 0;
	for (const auto& l : map)
	{
		const Eigen::Vector3d p = P_axes * l.p_FinW;
		const Eigen::Matrix3d P = P_axes * l.P * P_axes.transpose();
		Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(P);
		Eigen::Matrix3d R = es.eigenvectors();
		if (R.determinant() < 0) R.col(2) = -R.col(2);
		auto e = marker("ellipsoids_95", id, visualization_msgs::Marker::SPHERE, time_s);
		Eigen::Isometry3d T_EinW = Eigen::Isometry3d::Identity();
		T_EinW.linear() = R, T_EinW.translation() = p;
		e.pose = ros::toPoseMsg(T_EinW);
		const Eigen::Vector3d axes =
		    2.0 * (kChi2_3dof_95 * es.eigenvalues().cwiseMax(0.0)).cwiseSqrt();
		e.scale.x = std::max(axes.x(), 1e-3), e.scale.y = std::max(axes.y(), 1e-3);
		e.scale.z = std::max(axes.z(), 1e-3);
		e.color.r = l.known ? 0.2f : 1.0f, e.color.g = 0.6f, e.color.b = 0.2f, e.color.a = 0.35f;
		out.markers.push_back(e);
		auto c = marker("landmarks", id, visualization_msgs::Marker::SPHERE, time_s);
		c.pose.position.x = p.x(), c.pose.position.y = p.y(), c.pose.position.z = p.z();
		c.scale.x = c.scale.y = c.scale.z = 0.06;
		c.color.r = c.color.g = c.color.b = 0.1f, c.color.a = 1;
		out.markers.push_back(c);
		auto t = marker("labels", id, visualization_msgs::Marker::TEXT_VIEW_FACING, time_s);
		t.pose.position = c.pose.position;
		t.pose.position.z += 0.15;
		t.scale.z = 0.14;
		t.color.r = t.color.g = t.color.b = t.color.a = 1;
		t.text = l.label;
		out.markers.push_back(t);
		++id;
	}
	return out;
}

RobotView::RobotView(::ros::NodeHandle& nh, const geometry::BiSightHead& head,
                     const arm::RtxOptions& rtx, const arm::ArmMount& mount)
    : head_(head),
      rtx_(rtx),
      mount_(mount),
      estimate_(nh.advertise<geometry_msgs::PoseWithCovarianceStamped>(
          ros::topics::kEstimate, ros::topics::kPublisherQueue)),
      path_(nh.advertise<nav_msgs::Path>(ros::topics::kPath, ros::topics::kPublisherQueue, true)),
      tf_(nh.advertise<tf2_msgs::TFMessage>("/tf", ros::topics::kPublisherQueue)),
      object_(nh.advertise<geometry_msgs::PoseStamped>(ros::topics::kObjectPose,
                                                       ros::topics::kPublisherQueue, true)),
      stage_(
          nh.advertise<std_msgs::String>(ros::topics::kStage, ros::topics::kPublisherQueue, true)),
      map_(nh.advertise<visualization_msgs::MarkerArray>(ros::topics::kMap,
                                                         ros::topics::kPublisherQueue, true))
{
}

void RobotView::estimate(const mission::PathSample& s)
{
	last_time_s_ = s.device_time_s;
	geometry_msgs::PoseWithCovarianceStamped e;
	e.header.stamp = ros::toRosTime(s.device_time_s);
	e.header.frame_id = "world";
	e.pose.pose = ros::toPoseMsg(ros::planarPose(s.estimate));
	e.pose.covariance = ros::planarCovariance(s.P_vv);
	estimate_.publish(e);
	geometry_msgs::PoseStamped p;
	p.header = e.header;
	p.pose = e.pose.pose;
	path_msg_.header = e.header;
	path_msg_.poses.push_back(p);
	// the whole path each time costs its length: every few steps, and at the end, is enough
	if (path_msg_.poses.size() % kPathEverySteps == 1) path_.publish(path_msg_);
	// REP 105: world → odom is the estimate's correction of the dead reckoning
	publishTf(tf_, ros::toTransformMsg(
	                   ros::planarPose(s.estimate) * ros::planarPose(s.odometry).inverse(), "world",
	                   "odom", s.device_time_s));
	if (next) next->estimate(s);
}

void RobotView::measurement(const vision::CycleRecord& c)
{
	if (next) next->measurement(c);
}

void RobotView::recognised(const mission::SearchResult& r, const Eigen::Vector3d& xv,
                           const model::WireFrame& target)
{
	const Eigen::Isometry3d T_OinC0_m = geometry::inMetres(r.T_OinC0_mm);
	geometry_msgs::PoseStamped p;
	p.header.stamp = ros::toRosTime(last_time_s_);
	p.header.frame_id = "world";
	p.pose =
	    ros::toPoseMsg(toRosAxes(geometry::T_C0inW(xv, head_.options().head_height_m) * T_OinC0_m));
	object_.publish(p);
	if (next) next->recognised(r, xv, target);
}

void RobotView::graspPlanned(const mission::RetrievalResult& r)
{
	if (next) next->graspPlanned(r);
}

void RobotView::note(const mission::TimelineEvent& e)
{
	std_msgs::String s;
	s.data = e.stage + ": " + e.text;
	stage_.publish(s);
	if (next) next->note(e);
}

void RobotView::cameras(const hw::StereoImages& pair)
{
	// base_link (REP 103 axes) → c0 (thesis axes): the head's centre M_h above the ground
	const Eigen::Isometry3d T_C0inV = geometry::T_C0inW({0, 0, 0}, head_.options().head_height_m);
	Eigen::Isometry3d T_C0inBase = Eigen::Isometry3d::Identity();
	T_C0inBase.linear() = geometry::R_mrptFromThesis() * T_C0inV.linear();
	T_C0inBase.translation() = geometry::R_mrptFromThesis() * T_C0inV.translation();
	const double t = pair.time_s;
	publishTf(tf_, ros::toTransformMsg(T_C0inBase, "base_link", "c0", t));
	publishTf(tf_, ros::toTransformMsg(head_.T_CamCvInC0(geometry::Side::Left, pair.angles), "c0",
	                                   "left_camera", t));
	publishTf(tf_, ros::toTransformMsg(head_.T_CamCvInC0(geometry::Side::Right, pair.angles), "c0",
	                                   "right_camera", t));
}

void RobotView::arm(const hw::ArmJoints& joints)
{
	constexpr double kMPerMm = 1e-3;
	Eigen::Isometry3d T_AinC0 = mount_.T_C0inA.inverse();
	T_AinC0.translation() *= kMPerMm;
	Eigen::Isometry3d T_GinA = rtx_.T06(arm::RtxJoints::fromMmDeg(joints));
	T_GinA.translation() *= kMPerMm;
	publishTf(tf_, ros::toTransformMsg(T_AinC0, "c0", "arm_base", last_time_s_));
	publishTf(tf_, ros::toTransformMsg(T_GinA, "arm_base", "gripper", last_time_s_));
}

void RobotView::finished(const mission::MissionResult& r)
{
	map_.publish(mapMarkers(r.map, last_time_s_));
	path_.publish(path_msg_);
	std_msgs::String s;
	s.data = std::string("done: ") + (r.success ? "succeeded" : "failed: " + r.failure);
	stage_.publish(s);
}

}  // namespace mrolr::apps
