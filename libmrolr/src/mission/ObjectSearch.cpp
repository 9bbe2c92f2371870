// The pan sweep at a station and recognition in each view (thesis 6.4, 7.2.2).
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/mission/DockPlanner.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/TableCoverage.h>
#include <mrolr/recog/images/MutualOcclusion.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace mrolr::mission
{
namespace
{
/** Mean of the line endpoints and conic centres (the frame of @p wf). */
Eigen::Vector3d centreOf(const model::WireFrame& wf)
{
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	for (const auto& l : wf.lines) sum += l.p1 + l.p2;
	for (const auto& c : wf.conics) sum += c.centre;
	const size_t n = 2 * wf.lines.size() + wf.conics.size();
	return n ? Eigen::Vector3d(sum / static_cast<double>(n)) : sum;
}

/** @p plane_L moved into C0 (mm). */
recog::SupportPlane planeInC0(const recog::SupportPlane& plane_L, const Eigen::Isometry3d& T_LinC0_mm)
{
	const Eigen::Vector3d n_C0 = T_LinC0_mm.linear() * plane_L.n_S;
	recog::SupportPlane out;
	out.n_S = n_C0;
	out.d_mm = plane_L.d_mm - n_C0.dot(T_LinC0_mm.translation());
	return out;
}

/** What a sweep view's timeline note says of it. */
std::string verdict(const SearchResult& r)
{
	const auto confidence = std::to_string(r.recognition.confidence);
	if (r.found) return "recognised (confidence " + confidence + ")";
	if (!r.explained_by.empty())
		return "recognised (confidence " + confidence + ") but refused: the " + r.explained_by +
		       " model explains that place better";
	return "not recognised";
}
}  // namespace

std::vector<double> ObjectSearch::expectedTableHeights_mm(const Eigen::Isometry3d& T_LinC0_mm) const
{
	// C0 is head_height_m above the floor, +y up; L's origin is T_LinC0's translation from it
	const double L_above_floor_mm = 1000.0 * o_.bisight.head_height_m + T_LinC0_mm.translation().y();
	std::vector<double> out;
	for (const auto& t : o_.plan.tables) out.push_back(1000.0 * t.top_height_m - L_above_floor_mm);
	return out;
}

ObjectSearch::ObjectSearch(const MissionOptions& o, const model::WireFrame& target,
                           ViewSource views, const std::vector<model::WireFrame>& others)
    : o_(o),
      head_(o.bisight),
      recognizer_(target, o.recognition),
      footprint_(recog::footprintOf(target)),
      p_centreinO_mm_(centreOf(target)),
      views_(std::move(views))
{
	for (const auto& wf : others)
	{
		others_.emplace_back(wf, o.recognition);
		footprints_.push_back(recog::footprintOf(wf));
	}
}

std::vector<recog::RecognitionResult> ObjectSearch::othersIn(
    const SearchView& view, const recog::SceneContext& context) const
{
	std::vector<recog::RecognitionResult> out;
	for (const auto& other : others_) out.push_back(other.recognize(view.scene, context));
	return out;
}

std::optional<std::string> ObjectSearch::rivalAt(
    const recog::RecognitionResult& r, const std::vector<recog::RecognitionResult>& others,
    const Eigen::Vector3d& up_L) const
{
	std::vector<recog::PlacedAnswer> rivals;
	for (size_t i = 0; i < others.size(); ++i) rivals.push_back({&others[i], footprints_[i]});
	const auto k = recog::betterExplained({&r, footprint_}, rivals, up_L);
	if (!k) return {};
	return others[*k].model;
}

recog::RecognitionResult ObjectSearch::behindOthers(
    const SearchView& view, const recog::SceneContext& context,
    const recog::RecognitionResult& alone,
    const std::vector<recog::RecognitionResult>& others) const
{
	std::vector<const recog::Recognizer*> recs{&recognizer_};
	std::vector<recog::RecognitionResult> first{alone};
	for (const auto& other : others_) recs.push_back(&other);
	first.insert(first.end(), others.begin(), others.end());
	auto search = [&](size_t i, const recog::ImageVerifier& behind)
	{
		if (i != 0) return recog::RecognitionResult{};  // only the target is sought behind them
		recog::SceneContext behind_them = context;
		behind_them.images = std::cref(behind);
		behind_them.repeat = true;  // the target's first search was of this scene
		return recognizer_.recognize(view.scene, behind_them);
	};
	return recog::searchBehindFound(recs, first, *view.images,
	                                o_.image_verification.sample_spacing_mm, search)
	    .front();
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

SearchResult ObjectSearch::observe(const geometry::HeadAngles& angles, Timeline& timeline) const
{
	const SearchView view = views_(angles);
	SearchResult r;
	r.angles = angles;
	r.frame = view.frame;
	const auto t0 = std::chrono::steady_clock::now();
	// C0 stands level on the base: its +y is the scene's up (upright prior, expected-visible
	// verification; docs/recog.md).
	const Eigen::Vector3d up_L = head_.up_L(angles);
	const Eigen::Isometry3d T_LinC0_mm = geometry::inMm(head_.T_LinC0(angles));
	r.table_plane = recog::estimateTablePlane(view.scene, up_L, expectedTableHeights_mm(T_LinC0_mm));
	r.table_plane_C0 = planeInC0(r.table_plane.plane, T_LinC0_mm);
	recog::SceneContext context;
	context.up_S = up_L;
	if (view.images) context.images = std::cref(*view.images);
	if (r.table_plane.found) context.plane = r.table_plane.plane;
	r.recognition = recognizer_.recognize(view.scene, context);
	const bool database = view.images && !others_.empty();
	std::vector<recog::RecognitionResult> others;  // the other models in this view, once
	if (database && !r.recognition.found && o_.search.behind_found)
	{
		others = othersIn(view, context);
		r.recognition = behindOthers(view, context, r.recognition, others);
	}
	if (database && r.recognition.found && o_.search.rival_models)
	{
		if (others.empty()) others = othersIn(view, context);
		r.explained_by = rivalAt(r.recognition, others, up_L).value_or("");
	}
	r.compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	timeline.addCompute(r.compute_s);
	r.found = r.recognition.found && r.explained_by.empty();
	if (!r.found) return r;
	r.T_OinL_mm = r.recognition.T_OinS;
	r.T_OinC0_mm = T_LinC0_mm * r.T_OinL_mm;
	return r;
}

std::vector<double> ObjectSearch::sweepPans() const
{
	const auto& s = o_.search;
	std::vector<double> pans;
	for (double pan = s.pan_from_deg; pan <= s.pan_to_deg + 1e-9; pan += s.pan_step_deg)
		pans.push_back(pan);
	// Nothing recognised: look again between the first views (new pairs, other viewpoints).
	for (double pan = s.pan_from_deg + s.pan_step_deg / 2; pan < s.pan_to_deg; pan += s.pan_step_deg)
		pans.push_back(pan);
	return pans;
}

std::vector<std::vector<ObjectSearch::SweepView>> ObjectSearch::sweepPasses(
    const Eigen::Vector3d& xv_estimate) const
{
	auto label = [](const geometry::HeadAngles& a)
	{
		char buf[64];
		std::snprintf(buf, sizeof buf, "pan %.0f deg, tilt %.0f deg", a.pan * 180 / M_PI,
		              a.tilt * 180 / M_PI);
		return std::string(buf);
	};
	const PlanTable* table =
	    o_.search.cover_table ? tableInFront(o_.plan.tables, xv_estimate) : nullptr;
	const double half_fov_deg =
	    std::atan(0.5 * o_.bisight.image_width_px / o_.bisight.focal_px_u) * 180 / M_PI;
	if (table)
	{
		const double h = o_.bisight.head_height_m;
		const auto first = tableViews(*table, xv_estimate, h, half_fov_deg, o_.search.pan_step_deg);
		std::vector<std::vector<SweepView>> out(2);
		for (const auto& v : first) out[0].push_back({head_.fixate(v.p_fixinC0_m), ""});
		for (const auto& v : betweenViews(*table, xv_estimate, h, first))
			out[1].push_back({head_.fixate(v.p_fixinC0_m), ""});
		for (auto& pass : out)
			for (auto& v : pass) v.label = label(v.angles);
		if (!out[0].empty()) return out;
	}
	std::vector<std::vector<SweepView>> out(2);
	const auto pans = sweepPans();
	const size_t first = static_cast<size_t>(
	    std::floor((o_.search.pan_to_deg - o_.search.pan_from_deg) / o_.search.pan_step_deg + 1e-9)) + 1;
	for (size_t i = 0; i < pans.size(); ++i)
		out[i < first ? 0 : 1].push_back(
		    {sweepAngles(pans[i]),
		     "pan " + std::to_string(static_cast<int>(std::lround(pans[i]))) + " deg"});
	return out;
}

SearchResult ObjectSearch::sweep(Timeline& timeline, const Eigen::Vector3d& xv_estimate) const
{
	SearchResult last, best;
	int views = 0;
	for (const auto& pass : sweepPasses(xv_estimate))
	{
		for (const auto& v : pass)
		{
			timeline.advance(o_.search.head_move_time_s);
			last = observe(v.angles, timeline);
			last.views = ++views;
			timeline.note("view at " + v.label + ": " + verdict(last));
			if (last.found && (!best.found || last.recognition.confidence > best.recognition.confidence))
				best = last;
			if (best.found && o_.search.stop_at_first) break;
		}
		if (best.found)
		{
			best.views = views;
			return best;
		}
	}
	return last;
}

}  // namespace mrolr::mission
