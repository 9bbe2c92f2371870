// Calibrating T_C0inA with the hand's marker, where the robot stands (eq 6.7.2 over several poses).
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/mission/DockCalibration.h>
#include <mrolr/stereo/ArucoMarker.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>

namespace mrolr::mission
{
namespace
{
/** Wrist rolls tried, nearest the facing one first (degrees). */
constexpr int kRollStepDeg = 15, kRollSteps = 12;
/** Poses alternate between two heights this far apart, so the points span 3D. */
constexpr double kHeightStepMm = 60;
/** Presenting poses stay this far inside the wrist's reach (wrist_radius_max_mm). */
constexpr double kReachMarginMm = 20;
/** Spacing of the candidate presenting positions. */
constexpr double kGridStepMm = 40;

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
	return Eigen::AngleAxisd(a.transpose() * b).angle() * 180.0 / M_PI;
}
}  // namespace

namespace
{
using C = DockCalibrationOptions;
constexpr auto kOpt = util::Presence::Optional;  // calibration was added after the mission files

const util::OptionsBinder<C>& dockCalibrationBinder()
{
	static const auto b =
	    util::OptionsBinder<C>()
	        .flag("enabled", &C::enabled, kOpt)
	        .integer("poses", &C::poses, 3, 64, kOpt)
	        .integer("min_poses", &C::min_poses, 3, 64, kOpt)
	        .number("column_above_table_mm", &C::column_above_table_mm, 0, 1000, kOpt)
	        .number("spread_mm", &C::spread_mm, 10, 500, kOpt)
	        .number("max_rms_mm", &C::max_rms_mm, 0.01, 100, kOpt)
	        .number("max_change_mm", &C::max_change_mm, 0, 1000, kOpt)
	        .number("max_change_deg", &C::max_change_deg, 0, 90, kOpt);
	return b;
}
}  // namespace

void DockCalibrationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                const std::string& s)
{
	dockCalibrationBinder().load(c, s, *this);
	util::requireInRange(c, s, "min_poses", min_poses, 3, poses);
}

void DockCalibrationOptions::dump(std::ostream& out) const
{
	dockCalibrationBinder().dump(out, *this);
}

DockCalibrator::DockCalibrator(const DockCalibrationOptions& o, const arm::RtxOptions& rtx,
                               const arm::GraspFeasibilityOptions& grip,
                               const arm::MarkerOptions& marker, const geometry::BiSightHead& head,
                               double arm_move_time_s, double head_move_time_s)
    : o_(o), rtx_(rtx), marker_(marker), head_(head), ik_(rtx), kin_(rtx),
      body_(arm::rtxBody(rtx, grip, marker)), arm_move_time_s_(arm_move_time_s),
      head_move_time_s_(head_move_time_s)
{
	const geometry::HeadAngles zero;
	cameras_mm_ = {head.T_LinC0(zero).translation() * 1000.0,
	               head.T_RinC0(zero).translation() * 1000.0};
}

std::optional<arm::RtxJoints> DockCalibrator::facingHead(const Eigen::Vector3d& p_GinA_mm,
                                                         const Eigen::Vector2d& to_head_xy) const
{
	const double facing = std::atan2(to_head_xy.y(), to_head_xy.x());  // +x_G towards the head
	for (int k = 0; k <= 2 * kRollSteps; ++k)
	{
		const int step = (k % 2 ? 1 : -1) * ((k + 1) / 2);
		Eigen::Isometry3d T_GinA = Eigen::Isometry3d::Identity();
		T_GinA.linear() = Eigen::AngleAxisd(facing + step * kRollStepDeg * M_PI / 180.0,
		                                    Eigen::Vector3d::UnitZ())
		                      .toRotationMatrix();
		T_GinA.translation() = p_GinA_mm;
		const auto ik = ik_.solve(T_GinA);
		if (!ik.solutions.empty()) return ik.solutions.front().joints;
	}
	return std::nullopt;
}

bool DockCalibrator::markerInView(const arm::RtxJoints& j, const Eigen::Isometry3d& T_GinA,
                                  const Eigen::Isometry3d& T_AinC0) const
{
	const Eigen::Vector3d p = T_AinC0 * (T_GinA * marker_.p_MinG_mm);
	try
	{
		head_.fixate(p / 1000.0);
	}
	catch (const geometry::GeometryError&)
	{
		return false;  // beyond the head's joints
	}
	// the arm's own boxes (the hand's excepted: the plate faces the head in front of it) must
	// leave the lines of sight to the plate clear
	const double clear_mm = marker_.plateHalfMm();
	const auto boxes = arm::placeBody(body_, kin_, j, T_AinC0);
	for (size_t b = 0; b < boxes.size(); ++b)
	{
		if (body_[b].frame == 6) continue;
		for (const auto& c : cameras_mm_)
			if (arm::segmentMeetsBox(c, p, boxes[b], clear_mm)) return false;
	}
	return true;
}

std::vector<std::pair<Eigen::Isometry3d, arm::RtxJoints>> DockCalibrator::presentingPoses(
    const Eigen::Isometry3d& T_C0inA_nominal, const Eigen::Vector3d& p_OinC0_mm,
    double table_z_in_A_mm) const
{
	const Eigen::Vector2d object = (T_C0inA_nominal * p_OinC0_mm).head<2>();
	const Eigen::Isometry3d T_AinC0 = T_C0inA_nominal.inverse();
	const Eigen::Vector3d p_C0inA = T_C0inA_nominal.translation();
	// the column (the wrist centre's height) above the table, below its top
	const double d1 = std::min(table_z_in_A_mm + o_.column_above_table_mm,
	                           rtx_.d1_top_mm - kHeightStepMm - 1.0);
	// every grid point in reach whose marker the head can fixate and see past the arm…
	struct Candidate
	{
		double distance;
		Eigen::Isometry3d T_GinA;
		arm::RtxJoints j;
	};
	std::vector<Candidate> candidates;
	const double r_max = rtx_.wrist_radius_max_mm - kReachMarginMm;
	for (double x = -r_max; x <= r_max; x += kGridStepMm)
		for (double y = -r_max; y <= r_max; y += kGridStepMm)
			for (int level = 0; level < 2; ++level)
			{
				const Eigen::Vector3d p_GinA(x, y, d1 + rtx_.d6_mm + level * kHeightStepMm);
				if (p_GinA.head<2>().norm() > r_max) continue;
				const auto j = facingHead(p_GinA, (p_C0inA - p_GinA).head<2>());
				if (!j) continue;
				const Eigen::Isometry3d T_GinA = kin_.T06(*j);
				if (!markerInView(*j, T_GinA, T_AinC0)) continue;
				candidates.push_back({(p_GinA.head<2>() - object).norm(), T_GinA, *j});
			}
	// …nearest the object first, each at least spread_mm from those already taken
	std::sort(candidates.begin(), candidates.end(),
	          [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
	std::vector<std::pair<Eigen::Isometry3d, arm::RtxJoints>> out;
	for (const auto& c : candidates)
	{
		if (static_cast<int>(out.size()) >= o_.poses) break;
		const bool apart = std::all_of(out.begin(), out.end(), [&](const auto& taken)
		{
			return (taken.first.translation() - c.T_GinA.translation()).norm() >= o_.spread_mm;
		});
		if (apart) out.emplace_back(c.T_GinA, c.j);
	}
	return out;
}

void DockCalibrator::moveOverTop(hw::ArmDevice& arm, const arm::RtxJoints& j,
                                 DockCalibrationResult& r) const
{
	auto now = arm::RtxJoints::fromMmDeg(arm.joints());
	now.d1_mm = rtx_.d1_top_mm;  // up
	arm.moveTo(now.toMmDeg());
	arm::RtxJoints turned = j;  // turned at the top
	turned.d1_mm = rtx_.d1_top_mm;
	arm.moveTo(turned.toMmDeg());
	arm.moveTo(j.toMmDeg());  // down
	r.time_s += 3 * arm_move_time_s_;
}

std::optional<Eigen::Vector3d> DockCalibrator::sight(const Look& look,
                                                     const Eigen::Vector3d& predicted_inC0_mm,
                                                     DockCalibrationResult& r) const
{
	geometry::HeadAngles angles;
	try
	{
		angles = head_.fixate(predicted_inC0_mm / 1000.0);
	}
	catch (const geometry::GeometryError&)
	{
		return std::nullopt;  // beyond the head's joints
	}
	const auto pair = look(angles);
	r.time_s += head_move_time_s_;
	r.frames.push_back(pair.frame);
	const auto t0 = std::chrono::steady_clock::now();
	const cv::Mat left = pair.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat right = pair.right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const auto mL = stereo::findArucoMarker(left, marker_.aruco_id);
	const auto mR = mL ? stereo::findArucoMarker(right, marker_.aruco_id) : std::nullopt;
	std::optional<Eigen::Vector3d> p;
	if (mL && mR) try
		{
			const geometry::StereoPixels px{mL->centre_px.x(), mL->centre_px.y(), mR->centre_px.x(),
			                                mR->centre_px.y()};
			p = head_.triangulatePoint(px, pair.angles) * 1000.0;
		}
		catch (const geometry::GeometryError&)
		{
		}
	r.compute_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return p;
}

void DockCalibrator::judge(DockCalibrationResult& r, const Eigen::Isometry3d& T_C0inA_nominal) const
{
	r.change_mm = (r.fit.T_C0inA.translation() - T_C0inA_nominal.translation()).norm();
	r.change_deg = angleDeg(r.fit.T_C0inA.linear(), T_C0inA_nominal.linear());
	char buf[160];
	if (r.fit.rms_mm > o_.max_rms_mm)
		std::snprintf(buf, sizeof buf, "the fit's residual %.1f mm rms exceeds max_rms_mm = %.1f",
		              r.fit.rms_mm, o_.max_rms_mm);
	else if (r.change_mm > o_.max_change_mm || r.change_deg > o_.max_change_deg)
		std::snprintf(buf, sizeof buf,
		              "the fitted mount is %.1f mm, %.2f deg from the nominal (beyond max_change)",
		              r.change_mm, r.change_deg);
	else
	{
		r.calibrated = true, r.T_C0inA = r.fit.T_C0inA;
		return;
	}
	r.reason = buf;
}

DockCalibrationResult DockCalibrator::run(hw::ArmDevice& arm, const Look& look,
                                          const Eigen::Isometry3d& T_C0inA_nominal,
                                          const Eigen::Vector3d& p_OinC0_mm,
                                          double table_z_in_A_mm, Timeline& timeline) const
{
	DockCalibrationResult r;
	r.T_C0inA = T_C0inA_nominal;
	const auto t0 = std::chrono::steady_clock::now();
	const auto poses = presentingPoses(T_C0inA_nominal, p_OinC0_mm, table_z_in_A_mm);
	r.compute_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	r.poses_planned = static_cast<int>(poses.size());
	if (static_cast<int>(poses.size()) < o_.min_poses)
	{
		r.reason = std::to_string(poses.size()) + " presenting poses in reach, " +
		           std::to_string(o_.min_poses) + " needed";
		return r;
	}
	const arm::RtxJoints start = arm::RtxJoints::fromMmDeg(arm.joints());
	r.attempted = true;
	std::vector<Eigen::Vector3d> in_A, in_C0;
	for (const auto& [T_GinA, j] : poses)
	{
		moveOverTop(arm, j, r);
		const Eigen::Vector3d p_MinA = T_GinA * marker_.p_MinG_mm;
		if (const auto p = sight(look, T_C0inA_nominal.inverse() * p_MinA, r))
			in_A.push_back(p_MinA), in_C0.push_back(*p);
	}
	moveOverTop(arm, start, r);
	r.sightings = static_cast<int>(in_A.size());
	timeline.advance(r.time_s);
	timeline.addCompute(r.compute_s);
	if (r.sightings < o_.min_poses)
	{
		r.reason = "the marker was seen in both images at " + std::to_string(r.sightings) + " of " +
		           std::to_string(poses.size()) + " poses, " + std::to_string(o_.min_poses) +
		           " needed";
		return r;
	}
	try
	{
		r.fit = arm::fitHeadInArm(in_A, in_C0);
	}
	catch (const std::invalid_argument& e)
	{
		r.reason = e.what();
		return r;
	}
	judge(r, T_C0inA_nominal);
	return r;
}

}  // namespace mrolr::mission
