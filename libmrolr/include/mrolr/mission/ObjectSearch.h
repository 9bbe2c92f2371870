#pragma once
/** The object search at a station (thesis 6.4, 7.2.2): the head looks down at the table and pans
 * from pan_from_deg to pan_to_deg, then looks again between those views; each view gives a scene
 * wire-frame in the left camera L (mm) and the target model is sought in it; the first view that
 * recognises ends the sweep. Where a
 * view's scene comes from is the mission's choice (a ViewSource): reconstructed from the head's
 * stereo pair, or a simulated scene sensor in tests. */
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/Rivals.h>
#include <mrolr/recog/plane/TablePlaneEstimate.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** One search (one station). Poses in mm. */
struct SearchResult
{
	bool found = false;
	recog::RecognitionResult recognition;
	geometry::HeadAngles angles;  ///< head angles of the view that recognised
	Eigen::Isometry3d T_OinL_mm = Eigen::Isometry3d::Identity();   ///< recognised
	Eigen::Isometry3d T_OinC0_mm = Eigen::Isometry3d::Identity();  ///< recognised
	/** The camera frame of the view (hw::StereoImages::frame); none for a simulated scene. */
	std::optional<uint64_t> frame;
	/** The table top estimated from the view's scene (recog/plane/TablePlaneEstimate.h), and the same
	 * plane in C0 (mm): given to the recogniser with the up direction. */
	recog::TablePlaneEstimate table_plane;
	recog::SupportPlane table_plane_C0;
	int views = 0;
	double compute_s = 0;
	/** The target was recognised in this view but refused: this other model of the database was
	 * found at its place with a higher image score ([search] rival_models); empty otherwise. */
	std::string explained_by;
};

/** A view's scene wire-frame (L, mm) and, when image verification is on, the pair's edge
 * evidence for recog::Recognizer. */
struct SearchView
{
	model::WireFrame scene;
	std::shared_ptr<const recog::ImageVerifier> images;  ///< null: 3D verification only
	std::optional<uint64_t> frame;                       ///< the stereo pair's frame, if any
};
using ViewSource = std::function<SearchView(const geometry::HeadAngles&)>;

class ObjectSearch
{
 public:
	/** @p target: the model wire-frame (O, mm) the recogniser looks for; @p views: where a view's
	 * scene comes from (the head is moved to the angles by it); @p others: the database's other
	 * models, recognised in a view where the target is not, so that it is sought behind those
	 * found ([search] behind_found), or in a view where it is, to ask whether one of them
	 * explains its place better ([search] rival_models); may be empty. */
	ObjectSearch(const MissionOptions& o, const model::WireFrame& target, ViewSource views,
	             const std::vector<model::WireFrame>& others = {});
	/** Head angles of sweep position @p pan_deg (tilted by gaze_tilt_deg, verged on the table). */
	geometry::HeadAngles sweepAngles(double pan_deg) const;
	/** Head angles that fixate the centre of the target's wire-frame (its line endpoints and conic
	 * centres averaged, O) at the pose @p T_OinC0_mm: the re-observation of the visual
	 * verification looks straight at the object, gaze lowered to it and cameras verged on it. */
	geometry::HeadAngles fixationAngles(const Eigen::Isometry3d& T_OinC0_mm) const;
	/** One recognition in one view; fills every field of the result but views. */
	SearchResult observe(const geometry::HeadAngles& angles, Timeline& timeline) const;
	/** The sweep's pans (deg): pan_from_deg to pan_to_deg in pan_step_deg, then, should none of
	 * those recognise, once more half a step between them. */
	std::vector<double> sweepPans() const;
	/** One view of a sweep: head angles and how the timeline names it. */
	struct SweepView
	{
		geometry::HeadAngles angles;
		std::string label;
	};
	/** The sweep's two passes from the base at @p xv_estimate: with `cover_table`, the views
	 * covering the plan's table in front of it (TableCoverage.h) and those between them;
	 * otherwise (or with no table in front) sweepPans() at gaze_tilt_deg. */
	std::vector<std::vector<SweepView>> sweepPasses(const Eigen::Vector3d& xv_estimate) const;
	/** The whole sweep: the first pass, then, should none recognise, the second; with
	 * stop_at_first the first view that recognises ends it, otherwise the most confident
	 * answer of the pass wins. */
	SearchResult sweep(Timeline& timeline, const Eigen::Vector3d& xv_estimate) const;
	const geometry::BiSightHead& head() const { return head_; }

 private:
	/** The plan's table tops as heights along up from L's origin (mm): the prior of the table
	 * plane estimate (C0 stands head_height_m above the floor, +y up). */
	std::vector<double> expectedTableHeights_mm(const Eigen::Isometry3d& T_LinC0_mm) const;

	/** The other models' recognitions in @p view, in the order of others_. */
	std::vector<recog::RecognitionResult> othersIn(const SearchView& view,
	                                               const recog::SceneContext& context) const;

	/** The target sought again behind the other models found in @p view ([search]
	 * behind_found); @p alone: its recognition without them; @p others: othersIn(). */
	recog::RecognitionResult behindOthers(
	    const SearchView& view, const recog::SceneContext& context,
	    const recog::RecognitionResult& alone,
	    const std::vector<recog::RecognitionResult>& others) const;

	/** The other model found at @p r's place with a higher image score ([search] rival_models,
	 * recog::betterExplained); @p others: othersIn(); @p up_L: the view's up direction. */
	std::optional<std::string> rivalAt(const recog::RecognitionResult& r,
	                                   const std::vector<recog::RecognitionResult>& others,
	                                   const Eigen::Vector3d& up_L) const;

	const MissionOptions& o_;
	geometry::BiSightHead head_;
	recog::Recognizer recognizer_;
	std::vector<recog::Recognizer> others_;
	recog::Footprint footprint_;                ///< the target's
	std::vector<recog::Footprint> footprints_;  ///< the others'
	Eigen::Vector3d p_centreinO_mm_;  ///< centre of the target's wire-frame
	ViewSource views_;
};

}  // namespace mrolr::mission
