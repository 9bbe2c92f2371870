// The mission's retrieval stage: docking where the arm reaches, calibrating the dock, grasping.
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/geometry/PoseUnits.h>
#include "MissionImpl.h"
#include <mrolr/mission/DecisionLog.h>

#include <chrono>
#include <cmath>

namespace mrolr::mission
{
/** The object at @p T_OinW_m seen from C0 of the base at @p xv (mm). */
Eigen::Isometry3d Mission::Impl::predictedInC0(const Eigen::Isometry3d& T_OinW_m,
                                               const Eigen::Vector3d& xv) const
{
	return geometry::inMm(geometry::T_C0inW(xv, o.bisight.head_height_m).inverse() * T_OinW_m);
}

/** True when the base at @p xv could turn without meeting the plan's walls (no walls: true). */
bool Mission::Impl::clearOfWalls(const Eigen::Vector3d& xv) const
{
	return !o.plan.room ||
	       o.plan.room->wallDistance(xv.head<2>()) >= o.labmate.turnRadius() + kTurnMargin_m;
}

/** The object at @p T_OinC0_mm (mm) seen from the base at @p xv, in W (m). */
Eigen::Isometry3d Mission::Impl::inW(const Eigen::Isometry3d& T_OinC0_mm,
                                     const Eigen::Vector3d& xv) const
{
	return geometry::T_C0inW(xv, o.bisight.head_height_m) * geometry::inMetres(T_OinC0_mm);
}

void Mission::Impl::retrieve()
{
	r.timeline.beginStage("retrieve");
	auto reobserve = [&](const Eigen::Isometry3d& T_OinC0_mm) { return reobserveAt(T_OinC0_mm); };
	Eigen::Isometry3d T_OinW = inW(r.search.T_OinC0_mm, r.search_xv_estimate);
	const PlanTable* table = tableUnder(o.plan.tables, T_OinW.translation());
	double top_height_m = table ? table->top_height_m : 0.0;
	Retrieval retrieval(o, target);
	r.dock_calibration.T_C0inA = retrieval.mount();  // the mount used unless calibrated below
	self->setJoints(dev.arm->joints());
	retrieval.viewPast(*self);
	Sighting seen = sightingOf(r.search);
	const Eigen::Isometry3d& T_OinC0_mm = seen.T_OinC0_mm;
	std::optional<uint64_t> frame = r.search.frame;
	if (o.docking.drive_to_reach &&
	    !retrieval.feasibleAt(T_OinC0_mm, top_height_m, &r.docking.reasons_before))
	{
		r.docking.needed = true;
		if (!table)
			r.docking.reason = "the plan has no table to dock at";
		else if (const auto again = dockAndReobserve(retrieval, *table, T_OinW, top_height_m))
			seen = *again, frame = r.docking.frame;
		if (r.docking.found_again && !retrieval.feasibleAt(T_OinC0_mm, top_height_m))
		{  // the sweep from the dock found it elsewhere, out of reach: dock once more for that
			T_OinW = inW(seen.T_OinC0_mm, nav->estimate());
			table = tableUnder(o.plan.tables, T_OinW.translation());
			top_height_m = table ? table->top_height_m : 0.0;
			r.docking.docked_again = true;
			r.timeline.note("docking again, for the object the sweep found");
			if (table)
				if (const auto third = dockAndReobserve(retrieval, *table, T_OinW, top_height_m))
					seen = *third, frame = r.docking.frame;
		}
	}
	// the arm moves only for a grasp it will attempt (its mount within the refusal bounds)
	const bool may_grasp =
	    r.docking.needed ? r.docking.planned : retrieval.feasibleAt(T_OinC0_mm, top_height_m);
	if (may_grasp) dockArm();  // else the grasp is infeasible from here: the arm is not moved
	if (o.dock_calibration.enabled && may_grasp) calibrateDock(retrieval, T_OinC0_mm, top_height_m);
	r.retrieval = retrieval.run(seen, top_height_m, *dev.arm, reobserve, r.timeline);
	r.retrieval.frame = frame;
	if (decisions) decisions->graspPlanned(r.retrieval);
	r.retrieved = r.retrieval.retrieved;
	if (!r.retrieval.feasible) r.failure = "grasp not feasible: " + r.retrieval.reasons.front();
	if (!r.retrieval.feasible && r.docking.needed && !r.docking.planned)
		r.failure += " (docking: " + r.docking.reason + ")";
	if (r.retrieval.feasible && !r.retrieved)
		r.failure = "not retrieved: " + (r.retrieval.reasons.empty()
		                                     ? std::string("the gripper does not hold it")
		                                     : r.retrieval.reasons.back());
	if (r.retrieved) r.timeline.note("object held (jaws " + std::to_string(r.retrieval.width_lifted_mm) + " mm apart)");
	if (r.retrieved && o.place.enabled) placeOnBoard(retrieval.mount());
	undockArm();
}

/** The first candidate docking pose (DockPlanner.h) from which the grasp is feasible, driven to;
 * the object is recognised again from there. Returns its pose in C0 there (mm): recognised, or
 * predicted from the search and the navigation's estimate when not recognised; nothing when no
 * candidate gives a feasible grasp (the base has not moved). */
std::optional<Sighting> Mission::Impl::dockAndReobserve(const Retrieval& retrieval,
                                                                 const PlanTable& table,
                                                                 const Eigen::Isometry3d& T_OinW_m,
                                                                 double top_height_m)
{
	auto& d = r.docking;
	const auto t0 = std::chrono::steady_clock::now();
	{
		ComputeTimer timer(r.timeline);
		const auto candidates =
		    dockCandidates(o.plan.tables, table, T_OinW_m.translation(), nav->estimate(),
		                   o.dock.T_C0inA, o.bisight.head_height_m,
		                   o.navigation.table_clearance_m, o.docking);
		d.candidates = static_cast<int>(candidates.size());
		for (const auto& c : candidates)
		{
			++d.candidates_checked;
			if (!clearOfWalls(c.pose.xv_zxphi))
			{
				++d.candidates_near_walls;
				continue;
			}
			std::vector<std::string> why;
			if (!retrieval.feasibleAt(predictedInC0(T_OinW_m, c.pose.xv_zxphi), top_height_m, &why))
			{
				if (d.candidates_checked == 1) d.reasons_nearest = why;
				continue;
			}
			d.planned = true, d.chosen = c;
			break;
		}
	}
	d.compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (!d.planned)
	{
		d.reason = "none of " + std::to_string(d.candidates) + " docking poses round table." +
		           table.name + " gives a feasible grasp";
		if (d.candidates_near_walls > 0)
			d.reason += " (" + std::to_string(d.candidates_near_walls) +
			            " left out: the base could not turn there, too near the room's walls)";
		r.timeline.note("docking: " + d.reason);
		return std::nullopt;
	}
	const auto& xv = d.chosen.pose.xv_zxphi;
	r.timeline.note("docking at " + d.chosen.side + " (z " + std::to_string(xv[0]) + " m, x " +
	                std::to_string(xv[1]) + " m, " + std::to_string(xv[2] * 180 / M_PI) +
	                " deg), " + std::to_string(d.chosen.travel_m) + " m to drive");
	r.timeline.beginStage("dock");
	nav->driveTo(d.chosen.pose);
	r.timeline.beginStage("retrieve");
	const Eigen::Isometry3d predicted = predictedInC0(T_OinW_m, nav->estimate());
	SearchResult s;
	try
	{
		r.timeline.advance(o.search.head_move_time_s);
		s = search->observe(search->fixationAngles(predicted), r.timeline);
	}
	catch (const geometry::GeometryError& e)
	{
		r.timeline.note(std::string("docking: cannot fixate the object: ") + e.what());
	}
	d.frame = s.frame;
	d.recognised = d.reached = s.found;
	d.ambiguous = s.found && s.recognition.ambiguous;
	r.timeline.note(std::string("docking view: ") + (s.found ? "recognised" : "not recognised"));
	if (s.found) return sightingOf(s);
	// Not where the search put it: that sighting may have been a false match, so the table is
	// swept again from here, and what this sweep finds is grasped (or reported out of reach).
	d.swept_again = true;
	const SearchResult again = search->sweep(r.timeline, nav->estimate());
	r.timeline.note(std::string("docking: table swept again from the docking pose: ") +
	                (again.found ? "found" : "not found"));
	if (again.found)
	{
		d.found_again = d.recognised = d.reached = true;
		d.ambiguous = again.recognition.ambiguous;
		d.frame = again.frame;
		return sightingOf(again);
	}
	d.reason = "not recognised again at the docking pose, nor in a sweep of the table from there: "
	           "grasp planned on the pose predicted from the search and the navigation's estimate";
	return Sighting{predicted, {}};
}

void Mission::Impl::calibrateDock(Retrieval& retrieval, const Eigen::Isometry3d& T_OinC0_mm,
                                  double top_height_m)
{
	r.timeline.beginStage("dock_calibration");
	const DockCalibrator calibrator(o.dock_calibration, o.rtx, o.grasp, o.marker,
	                                geometry::BiSightHead(o.bisight), o.retrieval.arm_move_time_s,
	                                o.search.head_move_time_s);
	auto look = [this](const geometry::HeadAngles& a)
	{
		dev.head->moveTo(a);
		return grabStereo(StereoShot::Purpose::Calibration);
	};
	auto& c = r.dock_calibration;
	c = calibrator.run(*dev.arm, look, retrieval.mount(), T_OinC0_mm.translation(),
	                   retrieval.tableZinA(top_height_m, T_OinC0_mm.translation()), r.timeline);
	char buf[200];
	if (c.calibrated)
		std::snprintf(buf, sizeof buf,
		              "dock calibrated from %d of %d marker poses: %.2f mm rms, %.1f mm / %.2f deg "
		              "from the nominal mount",
		              c.sightings, c.poses_planned, c.fit.rms_mm, c.change_mm, c.change_deg);
	else
		std::snprintf(buf, sizeof buf, "dock not calibrated (%s): the nominal mount is used",
		              c.reason.c_str());
	r.timeline.note(buf);
	retrieval.setMount(c.T_C0inA);
	r.timeline.beginStage("retrieve");
}

/** The visual verification's view: the head fixates the object's estimated centre and a new
 * stereo pair is recognised as in the sweep. */
std::optional<Sighting> Mission::Impl::reobserveAt(const Eigen::Isometry3d& T_OinC0_mm)
{
	geometry::HeadAngles angles;
	try
	{
		angles = search->fixationAngles(T_OinC0_mm);
	}
	catch (const geometry::GeometryError& e)
	{
		r.timeline.note(std::string("verification: cannot fixate the object: ") + e.what());
		return std::nullopt;
	}
	r.timeline.advance(o.search.head_move_time_s);
	const auto s = search->observe(angles, r.timeline);
	r.timeline.note(std::string("verification view (object fixated): ") +
	                (s.found ? "recognised" : "not recognised"));
	return s.found ? std::optional(sightingOf(s)) : std::nullopt;
}

}  // namespace mrolr::mission
