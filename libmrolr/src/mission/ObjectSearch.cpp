// The pan sweep at a station and recognition in each view (thesis 6.4, 7.2.2).
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/recog/SyntheticScene.h>
#include <mrolr/sim/Placement.h>

#include <chrono>
#include <cmath>

namespace mrolr::mission
{
namespace
{
Eigen::Isometry3d toMm(Eigen::Isometry3d T)
{
	T.translation() *= 1000.0;
	return T;
}

/** True when the point (C0, m) projects inside the left image. */
bool inImage(const geometry::BiSightHead& head, const Eigen::Vector3d& p_C0,
             const geometry::HeadAngles& angles)
{
	try
	{
		const auto px = head.project(p_C0, angles);
		const auto& c = head.camera();
		return px.uL >= 0 && px.vL >= 0 && px.uL < c.width_px && px.vL < c.height_px;
	}
	catch (const geometry::GeometryError&)
	{
		return false;
	}
}

/** Mean of the line endpoints and conic centres (the frame of @p wf). */
Eigen::Vector3d centreOf(const model::WireFrame& wf)
{
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	for (const auto& l : wf.lines) sum += l.p1 + l.p2;
	for (const auto& c : wf.conics) sum += c.centre;
	const size_t n = 2 * wf.lines.size() + wf.conics.size();
	return n ? Eigen::Vector3d(sum / static_cast<double>(n)) : sum;
}

double rotationAngleDeg(const Eigen::Matrix3d& R)
{
	return Eigen::AngleAxisd(R).angle() * 180.0 / M_PI;
}
}  // namespace

WorldObjects placedObjects(const world::World& w)
{
	WorldObjects out;
	for (const auto& p : w.objects) out[p.name] = {p.model, sim::T_OinW(w, p)};
	return out;
}

ObjectSearch::ObjectSearch(const MissionOptions& o, const model::WireFrame& target,
                           const std::map<std::string, model::WireFrame>& models)
    : o_(o),
      head_(o.bisight),
      recognizer_(target, o.recognition),
      target_(o.target),
      p_centreinO_mm_(centreOf(target)),
      models_(models)
{
}

geometry::HeadAngles ObjectSearch::fixationAngles(const Eigen::Isometry3d& T_OinC0_mm) const
{
	return head_.fixate(T_OinC0_mm * p_centreinO_mm_ / 1000.0);
}

geometry::HeadAngles ObjectSearch::sweepAngles(double pan_deg) const
{
	// Verge on the point 0.8 m away along the gaze direction.
	const double pan = pan_deg * M_PI / 180.0, tilt = o_.search.gaze_tilt_deg * M_PI / 180.0;
	const Eigen::Vector3d dir(std::sin(pan) * std::cos(tilt), std::sin(tilt),
	                          std::cos(pan) * std::cos(tilt));
	return head_.fixate(0.8 * dir);
}

model::WireFrame ObjectSearch::sceneOf(const WorldObjects& objects,
                                       const Eigen::Isometry3d& T_C0inW,
                                       const geometry::HeadAngles& angles, std::mt19937& rng) const
{
	recog::SceneNoise noise;
	noise.endpoint_sigma_mm = o_.search.endpoint_sigma_mm;
	noise.missing_fraction = o_.search.missing_fraction;
	noise.fragment_probability = o_.search.fragment_probability;
	noise.hide_back_side = o_.search.hide_back_side;
	const Eigen::Isometry3d T_WinL = (T_C0inW * head_.T_LinC0(angles)).inverse();
	model::WireFrame scene;
	scene.frame = model::WireFrameFrame::LeftCamera;
	for (const auto& [name, obj] : objects)
	{
		const Eigen::Isometry3d T_OinL = T_WinL * obj.T_OinW;
		const Eigen::Vector3d p = T_OinL.translation();
		if (p.z() <= 0.05 || p.norm() > o_.search.max_object_range_m) continue;
		if (!inImage(head_, (T_C0inW.inverse() * obj.T_OinW).translation(), angles)) continue;
		const auto moved = recog::placeInScene(models_.at(obj.model), toMm(T_OinL));
		recog::appendWireFrame(scene, recog::corruptScene(moved, noise, rng));
	}
	return scene;
}

SearchResult ObjectSearch::observe(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
                                   const geometry::HeadAngles& angles, std::mt19937& rng,
                                   Timeline& timeline) const
{
	const StereoScene view = scene_from_stereo
	                             ? scene_from_stereo(angles)
	                             : StereoScene{sceneOf(objects, T_C0inW, angles, rng), {}};
	SearchResult r;
	r.angles = angles;
	const auto t0 = std::chrono::steady_clock::now();
	// C0 stands level on the base: its +y is the scene's up (upright prior, expected-visible
	// verification; docs/recog.md).
	const Eigen::Vector3d up_L = head_.up_L(angles);
	r.recognition = recognizer_.recognize(view.scene, &up_L, view.images.get());
	r.compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	timeline.addCompute(r.compute_s);
	r.found = r.recognition.found;
	if (!r.found) return r;
	r.T_OinL = r.recognition.T_OinS;
	Eigen::Isometry3d T_LinC0 = toMm(head_.T_LinC0(angles));
	r.T_OinC0 = T_LinC0 * r.T_OinL;
	compareWithTruth(objects, T_C0inW, r);
	return r;
}

void ObjectSearch::compareWithTruth(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
                                    SearchResult& r) const
{
	double best = 1e18;
	for (const auto& [name, obj] : objects)
	{
		if (obj.model != target_) continue;
		const Eigen::Isometry3d T_true = toMm(T_C0inW.inverse() * obj.T_OinW);
		const double d = (T_true.translation() - r.T_OinC0.translation()).norm();
		if (d >= best) continue;
		best = d;
		r.instance = name;
		r.T_OinC0_true = T_true;
		r.translation_error_mm = d;
		r.rotation_error_deg = rotationAngleDeg(T_true.linear().transpose() * r.T_OinC0.linear());
	}
}

SearchResult ObjectSearch::sweep(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
                                 std::mt19937& rng, Timeline& timeline) const
{
	SearchResult last;
	int views = 0;
	const auto& s = o_.search;
	for (double pan = s.pan_from_deg; pan <= s.pan_to_deg + 1e-9; pan += s.pan_step_deg)
	{
		timeline.advance(s.head_move_time_s);
		const auto angles = sweepAngles(pan);
		if (on_view) on_view(angles);
		last = observe(objects, T_C0inW, angles, rng, timeline);
		last.views = ++views;
		timeline.note("view at pan " + std::to_string(static_cast<int>(std::lround(pan))) +
		              " deg: " + (last.found ? "recognised" : "not recognised"));
		if (last.found) break;
	}
	return last;
}

}  // namespace mrolr::mission
