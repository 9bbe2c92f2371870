#pragma once
// What mrolr-ros-robot shows of itself on ROS (docs/ros.md "Watching it in RViz"): its estimate
// with covariance and its path, its estimated tf chain world → odom and base_link → cameras, the recognised
// object's pose, the mission's stage, and at the end its map with the 95 % ellipsoids. Only the
// robot's own beliefs: it reads no topic. Its frames (REP 105, the thesis's as children):
// world → odom → base_link (the lab's dead reckoning) → c0 (the head's centre, thesis axes) →
// left_camera, right_camera (optical) and → arm_base → gripper (its kinematics and mount).
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/mission/DecisionLog.h>
#include <mrolr/mission/Mission.h>

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <memory>

namespace mrolr::apps
{
/** The map as markers in `world` (REP 105 axes): a sphere per landmark, its 95 % ellipsoid
 * (χ²₃ = 7.815) as a translucent scaled sphere, and its label. */
visualization_msgs::MarkerArray mapMarkers(const std::vector<mission::MappedLandmark>& map,
                                           double time_s);

class RobotView : public mission::DecisionLog
{
 public:
	RobotView(::ros::NodeHandle& nh, const geometry::BiSightHead& head, const arm::RtxOptions& rtx,
	          const arm::ArmMount& mount);
	/** Also gets every decision (the recording); may be null. */
	mission::DecisionLog* next = nullptr;
	void estimate(const mission::PathSample& s) override;
	void measurement(const vision::CycleRecord& c) override;
	void recognised(const mission::SearchResult& r, const Eigen::Vector3d& xv_estimate,
	                const model::WireFrame& target) override;
	void graspPlanned(const mission::RetrievalResult& r) override;
	void note(const mission::TimelineEvent& e) override;
	/** The cameras where the robot's calibration puts them at @p pair's angles (tf). */
	void cameras(const hw::StereoImages& pair);
	/** The arm where its mount and kinematics put it at @p joints (tf c0 → arm_base → gripper). */
	void arm(const hw::ArmJoints& joints);
	/** The final map and stage (latched, so a late RViz still sees them). */
	void finished(const mission::MissionResult& r);

 private:
	geometry::BiSightHead head_;
	arm::RtxKinematics rtx_;
	arm::ArmMount mount_;
	::ros::Publisher estimate_, path_, tf_, object_, stage_, map_;
	nav_msgs::Path path_msg_;  ///< the estimates so far
	double last_time_s_ = 0;
};

/** A head whose grabs also go to RobotView::cameras. */
class ViewedHead : public hw::HeadDevice
{
 public:
	ViewedHead(hw::HeadDevice& head, RobotView& view) : head_(head), view_(view) {}
	double moveTo(const geometry::HeadAngles& t) override { return head_.moveTo(t); }
	geometry::HeadAngles angles() const override { return head_.angles(); }
	hw::StereoImages grab() override
	{
		auto pair = head_.grab();
		view_.cameras(pair);
		return pair;
	}

 private:
	hw::HeadDevice& head_;
	RobotView& view_;
};

/** An arm whose moves also go to RobotView::arm. */
class ViewedArm : public hw::ArmDevice
{
 public:
	ViewedArm(hw::ArmDevice& arm, RobotView& view) : arm_(arm), view_(view) {}
	void moveTo(const hw::ArmJoints& j) override
	{
		arm_.moveTo(j);
		view_.arm(arm_.joints());
	}
	hw::ArmJoints joints() const override { return arm_.joints(); }
	void setGripper(bool closed) override { arm_.setGripper(closed); }
	bool gripperClosed() const override { return arm_.gripperClosed(); }
	double gripperWidthMm() const override { return arm_.gripperWidthMm(); }
	void dock(bool docked) override { arm_.dock(docked); }
	bool docked() const override { return arm_.docked(); }

 private:
	hw::ArmDevice& arm_;
	RobotView& view_;
};

}  // namespace mrolr::apps
