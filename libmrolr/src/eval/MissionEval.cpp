// The robot's report against the truth: home, held object, recognised pose, NEES, collisions.
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/eval/MissionEval.h>
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/slam/Chi2.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::eval
{
namespace
{
using nlohmann::json;

const json& need(const json& j, const char* key)
{
	if (!j.is_object() || !j.contains(key))
		throw std::runtime_error(std::string("report: missing field '") + key + "'");
	return j.at(key);
}

Eigen::Vector3d vec3(const json& v)
{
	return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

Eigen::Matrix3d mat3(const json& m)
{
	Eigen::Matrix3d M;
	for (int i = 0; i < 3; ++i)
		for (int k = 0; k < 3; ++k) M(i, k) = m.at(i).at(k).get<double>();
	return M;
}

double angleDeg(const Eigen::Matrix3d& R)
{
	return Eigen::AngleAxisd(R).angle() * 180.0 / M_PI;
}

void homeErrors(json& r, const MissionTruth& t)
{
	const json& robot = need(r, "robot");
	const Eigen::Vector3d home = vec3(need(need(robot, "home"), "zxphi"));
	const double tol = need(robot, "home_tolerance_m").get<double>();
	const double err = (t.final_zxphi.head<2>() - home.head<2>()).norm();
	r["final_position_error_m"] = err;
	r["final_heading_error_deg"] =
	    std::abs(base::wrapAngle(t.final_zxphi.z() - home.z())) * 180.0 / M_PI;
	r["final_estimate_error_m"] =
	    (vec3(need(robot, "final_estimate_zxphi")).head<2>() - t.final_zxphi.head<2>()).norm();
	r["dead_reckoning_error_m"] =
	    (vec3(need(robot, "final_odometry_zxphi")).head<2>() - t.final_zxphi.head<2>()).norm();
	r["eval"]["home_error_m"] = err;
	r["eval"]["returned_home"] = err <= tol;
}

void heldObject(json& r, const MissionTruth& t)
{
	const std::string target = need(r, "target").get<std::string>();
	auto modelOf = [&](const std::string& name)
	{
		for (const auto& o : t.objects)
			if (o.name == name) return o.model;
		return std::string();
	};
	std::string aboard;  // the target's instance riding on the deck
	for (const auto& n : t.on_board)
		if (modelOf(n) == target) aboard = n;
	r["eval"]["held_instance"] = t.held.empty() ? json(nullptr) : json(t.held);
	r["eval"]["object_held"] = !t.held.empty() && modelOf(t.held) == target;
	r["eval"]["on_board_instance"] = aboard.empty() ? json(nullptr) : json(aboard);
	r["eval"]["object_on_board"] = !aboard.empty();
	r["eval"]["object_retrieved"] =
	    r["eval"]["object_held"].get<bool>() || r["eval"]["object_on_board"].get<bool>();
	r["eval"]["gripper_events"] = gripperEventsJson(t.gripper_events);
	json disturbed = json::array();
	for (const auto& o : t.objects)
	{
		if (o.name == t.held || o.name == aboard) continue;
		const double moved_mm = 1000.0 * (o.T_OinW.translation() - o.T_OinW_start.translation()).norm();
		const double tilt_deg =
		    std::acos(std::clamp(o.T_OinW.linear().col(2).dot(o.T_OinW_start.linear().col(2)), -1.0, 1.0)) *
		    180.0 / M_PI;
		if (moved_mm > 2 || tilt_deg > 5)
			disturbed.push_back({{"name", o.name}, {"moved_mm", moved_mm}, {"fell", tilt_deg > 45}});
	}
	r["eval"]["objects_disturbed"] = disturbed;
}

const sim::TruthLog::Frame* frameOf(const MissionTruth& t, const json& recognition)
{
	const json& f = need(recognition, "frame");
	if (f.is_null()) return nullptr;
	for (const auto& fr : t.frames)
		if (fr.frame == f.get<uint64_t>()) return &fr;
	return nullptr;
}

/** The target-model object nearest to the recognised pose; its true pose in C0 (mm). */
struct Match
{
	std::string instance;
	Eigen::Isometry3d T_true = Eigen::Isometry3d::Identity();
	double translation_mm = std::numeric_limits<double>::infinity(), rotation_deg = 0;
	bool in_C0 = false;
	std::vector<double> symmetry_deg;  ///< the object's, which rotation_deg is taken modulo
};

Match matchObject(const json& r, const MissionTruth& t)
{
	const json& rec = need(need(r, "robot"), "recognition");
	const std::string target = need(r, "target").get<std::string>();
	const Eigen::Isometry3d T_OinC0 = mission::isometryFrom(need(rec, "T_OinC0_mm"));
	const double h = need(need(r, "robot"), "head_height_m").get<double>();
	const auto* frame = frameOf(t, rec);
	const Eigen::Isometry3d T_C0inW_est =
	    geometry::inMm(geometry::T_C0inW(vec3(need(rec, "search_estimate_zxphi")), h));
	Match best;
	for (const auto& o : t.objects)
	{
		if (o.model != target) continue;
		Eigen::Isometry3d T_true, T_est;
		if (frame)  // both in C0 at the recognising frame
			T_true = geometry::inMm(frame->T_C0inW.inverse() * frame->T_OinW.at(o.name)),
			T_est = T_OinC0;
		else  // both in W, the estimate through the robot's own pose estimate
			T_true = geometry::inMm(o.T_OinW_start), T_est = T_C0inW_est * T_OinC0;
		const double d = (T_true.translation() - T_est.translation()).norm();
		if (d >= best.translation_mm) continue;
		best = {o.name, T_true, d,
		        rotationErrorDeg(T_true.linear(), T_est.linear(), o.symmetry_deg),
		        frame != nullptr, o.symmetry_deg};
	}
	return best;
}

void retrievalErrors(json& r, const Match& m, const MissionTruth& t)
{
	if (!m.in_C0 || !r.contains("retrieval") || !t.T_C0inA_mm) return;
	json& g = r["retrieval"];
	if (!need(g, "feasible").get<bool>()) return;
	// the grasp was planned in C0 of the retrieval's own view (after docking, not the search's)
	Eigen::Isometry3d T_true = m.T_true;
	if (g.contains("frame") && !g.at("frame").is_null())
	{
		const auto* fr = frameOf(t, g);
		if (!fr) return;
		T_true = geometry::inMm(fr->T_C0inW.inverse() * fr->T_OinW.at(m.instance));
	}
	const auto first = mission::isometryFrom(need(g, "T_OinC0_first_mm"));
	g["object_error_before_mm"] = (first.translation() - T_true.translation()).norm();
	if (need(g, "verified").get<bool>())
		g["object_error_after_mm"] =
		    (mission::isometryFrom(need(g, "T_OinC0_verified_mm")).translation() -
		     T_true.translation())
		        .norm();
	const Eigen::Isometry3d T_GinA_true =
	    *t.T_C0inA_mm * T_true * mission::isometryFrom(need(g, "T_GinO_mm"));
	g["grasp_error_mm"] =
	    (mission::isometryFrom(need(g, "T_GinA_mm")).translation() - T_GinA_true.translation())
	        .norm();
}

/** The estimated table top against the true one under the found object, in C0 at the
 * recognising frame: the height of the true top's point under the object above the estimate
 * (mm) and the angle between the normals (deg). */
void tablePlaneError(json& r, const Match& m, const MissionTruth& t)
{
	const json& est = need(need(r, "robot"), "recognition");
	if (!t.world || !est.contains("table_plane_C0") || est.at("table_plane_C0").is_null()) return;
	const world::PlacedObject* placed = nullptr;
	for (const auto& o : t.world->objects)
		if (o.name == m.instance) placed = &o;
	const world::Table* table = placed ? t.world->findTable(placed->table) : nullptr;
	if (!table) return;
	const json& p = est.at("table_plane_C0");
	const Eigen::Vector3d n_est(p.at("n")[0].get<double>(), p.at("n")[1].get<double>(),
	                            p.at("n")[2].get<double>());
	const double d_est = p.at("d_mm").get<double>();
	// m.T_true: the object in C0 (mm); its origin is the centre of its footprint on the top
	const Eigen::Vector3d p_C0 = m.T_true.translation();
	const double height_mm = n_est.dot(p_C0) + d_est;
	// the true top is level: its normal in C0 is W's up seen from C0, which stands level too
	const auto* frame = frameOf(t, need(need(r, "robot"), "recognition"));
	if (!frame) return;
	const Eigen::Vector3d n_true = frame->T_C0inW.linear().transpose() * Eigen::Vector3d::UnitY();
	auto& out = r["recognition"]["table_plane"];
	out["error_mm"] = std::abs(height_mm);
	out["error_deg"] = std::acos(std::clamp(n_est.normalized().dot(n_true), -1.0, 1.0)) * 180.0 / M_PI;
}

/** The mount the grasp chain used against the true one: where the arm base stands in C0 (mm)
 * and the angle between the rotations (deg); the nominal's error too (the dock's). */
void dockCalibrationErrors(json& r, const MissionTruth& t)
{
	if (!t.T_C0inA_mm || !r.contains("retrieval")) return;
	json& g = r["retrieval"];
	if (!g.contains("dock_calibration")) return;
	const auto used = mission::isometryFrom(need(g["dock_calibration"], "T_C0inA_mm"));
	const auto nominal = mission::isometryFrom(need(need(r, "robot"), "dock_T_C0inA_mm"));
	auto error = [&t](const Eigen::Isometry3d& T, const char* mm_key, const char* deg_key, json& out)
	{
		out[mm_key] = (T.inverse().translation() - t.T_C0inA_mm->inverse().translation()).norm();
		out[deg_key] = angleDeg(T.linear().transpose() * t.T_C0inA_mm->linear());
	};
	error(used, "dock_calibration_error_mm", "dock_calibration_error_deg", g);
	error(nominal, "dock_error_mm", "dock_error_deg", g);
}

void objectErrors(json& r, const MissionTruth& t)
{
	dockCalibrationErrors(r, t);
	if (!need(r, "found").get<bool>()) return;
	const Match m = matchObject(r, t);
	if (m.instance.empty()) return;
	r["found_instance"] = m.instance;
	r["object_translation_error_mm"] = m.translation_mm;
	r["object_rotation_error_deg"] = m.rotation_deg;
	r["eval"]["object_symmetry_deg"] = m.symmetry_deg;
	r["eval"]["object_pose_frame"] = m.in_C0 ? "C0 at the recognising frame" : "W";
	if (m.in_C0) r["recognition"]["T_OinC0_true_mm"] = mission::matrix34(m.T_true);
	if (m.in_C0) tablePlaneError(r, m, t);
	retrievalErrors(r, m, t);
}

/** NEES of the vehicle estimate at every step whose truth is known (3 dof). */
void vehicleNees(json& r, const MissionTruth& t)
{
	if (t.steps.empty()) return;
	const double lo = slam::chi2Quantile(0.025, 3), hi = slam::chi2Quantile(0.975, 3);
	double sum = 0;
	int n = 0, inside = 0;
	size_t k = 0;
	for (const auto& s : need(need(r, "robot"), "path"))
	{
		const double time = need(s, "device_t_s").get<double>();
		// 1 µs: a rawlog's timestamps carry the step times to about 0.2 µs (after a replay)
		while (k + 1 < t.steps.size() && t.steps[k + 1].time_s <= time + 1e-6) ++k;
		const Eigen::Matrix3d P = mat3(need(s, "P_vv"));
		if (std::abs(t.steps[k].time_s - time) > 1e-6 || P.determinant() <= 1e-18) continue;
		Eigen::Vector3d e = vec3(need(s, "estimate")) - t.steps[k].xv_zxphi;
		e.z() = base::wrapAngle(e.z());
		const double nees = e.dot(P.ldlt().solve(e));
		sum += nees, ++n, inside += nees >= lo && nees <= hi;
	}
	r["eval"]["nees"] = {{"count", n},
	                     {"mean", n ? json(sum / n) : json(nullptr)},
	                     {"bounds_95", {lo, hi}},
	                     {"fraction_inside_95", n ? json(double(inside) / n) : json(nullptr)}};
}

void collision(json& r, const MissionTruth& t)
{
	if (!t.contact)
	{
		r["eval"]["collision"] = nullptr;
		return;
	}
	r["eval"]["collision"] = {
	    {"what", t.contact->what}, {"z_m", t.contact->p_zx.x()}, {"x_m", t.contact->p_zx.y()}};
	std::string& f = r["failure"].get_ref<std::string&>();
	f += (f.empty() ? "" : "; ") + std::string("eval: hit ") + t.contact->what + " at (z " +
	     std::to_string(t.contact->p_zx.x()) + ", x " + std::to_string(t.contact->p_zx.y()) +
	     ") m";
}

void verdict(json& r)
{
	json& e = r["eval"];
	const bool ok = e["object_retrieved"].get<bool>() && e["returned_home"].get<bool>() &&
	                e["collision"].is_null();
	e["mission_success"] = ok;
	e["agrees_held"] = e["object_retrieved"].get<bool>() == need(r, "retrieved").get<bool>();
	e["agrees_home"] = e["returned_home"].get<bool>() == need(r, "returned_home").get<bool>();
	const bool claimed = need(need(r, "robot"), "success").get<bool>();
	e["confirms"] = claimed && ok;
	r["success"] = claimed && ok;
	if (claimed && !ok && r["failure"].get<std::string>().empty())
		r["failure"] = std::string("eval: the robot claimed success but ") +
		               (!e["object_retrieved"].get<bool>()
		                    ? "the target is neither in the gripper nor on the deck"
		                                               : "it is not home");
}
}  // namespace

void evaluateMission(json& report, const MissionTruth& truth)
{
	report["eval"] = json::object();
	report["eval"]["ran"] = true;
	homeErrors(report, truth);
	heldObject(report, truth);
	objectErrors(report, truth);
	vehicleNees(report, truth);
	collision(report, truth);
	verdict(report);
}

}  // namespace mrolr::eval
