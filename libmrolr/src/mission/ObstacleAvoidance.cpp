// Looks ahead before each translation step and inserts waypoints round obstacles (5.8.1.2).
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/ObstacleAvoidance.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mrolr::mission
{
Eigen::Vector2d baseToWorld(const Eigen::Vector3d& xv, const Eigen::Vector2d& p)
{
	const double c = std::cos(xv.z()), s = std::sin(xv.z());
	return {xv.x() + c * p.x() - s * p.y(), xv.y() + s * p.x() + c * p.y()};
}

ObstacleAvoidance::ObstacleAvoidance(const geometry::BiSightHead& head,
                                     const ObstacleOptions& options, Grab grab, Timeline& timeline)
    : head_(head), o_(options), grab_(std::move(grab)), timeline_(timeline), stereo_(head, options)
{
}

geometry::HeadAngles ObstacleAvoidance::lookAngles(double pan_deg) const
{
	const double pan = pan_deg * M_PI / 180.0, tilt = o_.tilt_deg * M_PI / 180.0;
	const Eigen::Vector3d dir(std::sin(pan) * std::cos(tilt), std::sin(tilt),
	                          std::cos(pan) * std::cos(tilt));
	return head_.fixate(o_.fixation_distance_m * dir);
}

std::vector<Eigen::Vector3d> ObstacleAvoidance::look(double pan_deg)
{
	const auto angles = lookAngles(pan_deg);
	const auto images = grab_(angles);
	++report_.looks;
	timeline_.advance(o_.look_time_s);
	ComputeTimer t(timeline_);
	auto p = stereo_.pointsAboveFloor(images.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY),
	                                  images.right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY),
	                                  images.angles);
	const double h = head_.options().head_height_m;
	if (self_)  // B → C0: the head centre is h above B
		p.erase(std::remove_if(p.begin(), p.end(),
		                       [this, h](const Eigen::Vector3d& q)
		                       { return self_->isSelf(q - Eigen::Vector3d(0, h, 0)); }),
		        p.end());
	if (!tables_.empty())
		p.erase(std::remove_if(p.begin(), p.end(),
		                       [this](const Eigen::Vector3d& q) { return onKnownTable(q); }),
		        p.end());
	return p;
}

void ObstacleAvoidance::lookAround(ObstacleEvent& e, std::vector<Eigen::Vector3d> points)
{
	for (double pan : {o_.side_pan_deg, -o_.side_pan_deg})
	{
		const auto side = look(pan);
		points.insert(points.end(), side.begin(), side.end());
	}
	ComputeTimer t(timeline_);
	// the side looks may show more of a wide obstacle: measure it again with every point
	const double near_m = e.sighting.near_m;
	if (const auto seen = obstacleAhead(points, near_m + o_.range_m, o_); seen.blocked)
		e.sighting = seen, e.sighting.near_m = near_m;
	e.detour = planDetour(e.sighting, points, o_);
}

void ObstacleAvoidance::setKnownTables(const std::vector<PlanTable>& tables, double margin_m)
{
	tables_ = tables;
	table_margin_m_ = margin_m;
}

bool ObstacleAvoidance::onKnownTable(const Eigen::Vector3d& p_inB) const
{
	const Eigen::Vector2d p = baseToWorld(xv_, {p_inB.z(), p_inB.x()});
	for (const auto& t : tables_)
	{
		const double yaw = t.yaw_deg * M_PI / 180.0;
		const Eigen::Vector2d d = p - Eigen::Vector2d(t.z_m, t.x_m);
		const double along_z = d.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw)));
		const double along_x = d.dot(Eigen::Vector2d(-std::sin(yaw), std::cos(yaw)));
		if (std::abs(along_z) <= t.depth_m / 2 + table_margin_m_ &&
		    std::abs(along_x) <= t.length_m / 2 + table_margin_m_)
			return true;
	}
	return false;
}

namespace
{
/** A clear look ahead (measured from the base's centre) covers the steps whose start stays this
 * much short of its far end (m): half the base's length and one 20 cm step, so that its front
 * never enters floor no look has seen ... */
constexpr double kLookCoverSlack_m = 0.6;
/** ... on about the same heading (rad). */
constexpr double kLookCoverTurn_rad = 10.0 * M_PI / 180.0;
}  // namespace

bool ObstacleAvoidance::coveredByLastLook(const Eigen::Vector3d& xv) const
{
	if (!last_clear_) return false;
	const Eigen::Vector2d d = xv.head<2>() - last_clear_->head<2>();
	const Eigen::Vector2d dir(std::cos(last_clear_->z()), std::sin(last_clear_->z()));
	return std::abs(std::remainder(xv.z() - last_clear_->z(), 2 * M_PI)) < kLookCoverTurn_rad &&
	       d.dot(dir) >= -0.05 && d.norm() < last_clear_length_m_ - kLookCoverSlack_m;
}

std::vector<Eigen::Vector2d> ObstacleAvoidance::check(const Eigen::Vector3d& xv,
                                                      const Eigen::Vector3d& goal)
{
	if (coveredByLastLook(xv)) return {};
	++report_.checks;
	xv_ = xv;
	last_clear_.reset();
	try
	{
		const auto ahead = look(0);
		const double to_goal = (goal.head<2>() - xv.head<2>()).norm();
		// the area the robot sweeps up to the goal, or up to range_m when the goal is further
		const double length = std::min(o_.range_m, to_goal);
		ObstacleEvent e;
		e.time_s = timeline_.simulatedSeconds();
		e.xv_estimate = xv;
		e.sighting = obstacleAhead(ahead, length, o_, to_goal <= o_.range_m);
		if (!e.sighting.blocked)
		{
			last_clear_ = xv, last_clear_length_m_ = length;
			return {};
		}
		lookAround(e, ahead);
		for (const auto& v : e.detour.via_zx) e.via_zx_inW.push_back(baseToWorld(xv, v));
		note(e);
		report_.events.push_back(e);
		return e.via_zx_inW;
	}
	catch (const hw::DeviceFailure&)
	{
		throw;  // the head stopped answering: the mission stops
	}
	catch (const std::exception& ex)
	{  // a failed look (rendering, matching) is recorded; the step goes ahead unchecked
		if (++report_.failed_looks == 1)
			timeline_.note(std::string("obstacle look failed (noted once): ") + ex.what());
		return {};
	}
}

void ObstacleAvoidance::note(const ObstacleEvent& e)
{
	std::ostringstream s;
	s.precision(2);
	s << std::fixed << "obstacle " << e.sighting.near_m << " m ahead (" << e.sighting.points
	  << " points, x " << e.sighting.right_m << ".." << e.sighting.left_m << " m, far edge "
	  << e.sighting.far_m << " m); passing on the " << (e.detour.side > 0 ? "left" : "right")
	  << (e.detour.both_blocked ? " (neither side free)" : "") << " via";
	for (const auto& v : e.via_zx_inW) s << " (" << v.x() << ", " << v.y() << ")";
	timeline_.note(s.str());
}

}  // namespace mrolr::mission
