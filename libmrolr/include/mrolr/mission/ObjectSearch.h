#pragma once
/** The object search at a station (thesis 6.4, 7.2.2): the head looks down at the table and pans
 * from pan_from_deg to pan_to_deg; each view gives a scene wire-frame in the left camera L (mm)
 * and the target model is sought in it; the first view that recognises ends the sweep.
 *
 * Simplification (docs/mission.md): the scene wire-frame of a view is not reconstructed from
 * rendered stereo images but simulated: the exact wire-frames (sim::objectWireFrame) of the
 * objects whose origin the left camera sees, moved by their true T_OinL and corrupted by
 * recog::corruptScene (endpoint noise, missing and fragmented segments, hidden back side). */
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>

#include <Eigen/Geometry>
#include <functional>
#include <map>
#include <memory>
#include <random>

namespace mrolr::mission
{
/** The objects of the simulated world: instance name → (model, true T_OinW in m). */
struct WorldObject
{
	std::string model;
	Eigen::Isometry3d T_OinW = Eigen::Isometry3d::Identity();
};
using WorldObjects = std::map<std::string, WorldObject>;

/** The placed objects of @p w with their true poses (O stands on the table top, z up). */
WorldObjects placedObjects(const world::World& w);

/** One search (one station). Poses in mm. */
struct SearchResult
{
	bool found = false;
	recog::RecognitionResult recognition;
	geometry::HeadAngles angles;  ///< head angles of the view that recognised
	Eigen::Isometry3d T_OinL = Eigen::Isometry3d::Identity();   ///< recognised, mm
	Eigen::Isometry3d T_OinC0 = Eigen::Isometry3d::Identity();  ///< recognised, mm
	std::string instance;  ///< the true object nearest to the recognised pose ("" if none)
	Eigen::Isometry3d T_OinC0_true = Eigen::Isometry3d::Identity();  ///< mm
	double rotation_error_deg = 0, translation_error_mm = 0;
	int views = 0;
	double compute_s = 0;
};

class ObjectSearch
{
 public:
	/** @p target: the model wire-frame (O, mm) the recogniser looks for. */
	ObjectSearch(const MissionOptions& o, const model::WireFrame& target,
	             const std::map<std::string, model::WireFrame>& models);
	/** Head angles of sweep position @p pan_deg (tilted by gaze_tilt_deg, verged on the table). */
	geometry::HeadAngles sweepAngles(double pan_deg) const;
	/** Head angles that fixate the centre of the target's wire-frame (its line endpoints and conic
	 * centres averaged, O) at the pose @p T_OinC0_mm: the re-observation of the visual
	 * verification looks straight at the object, gaze lowered to it and cameras verged on it. */
	geometry::HeadAngles fixationAngles(const Eigen::Isometry3d& T_OinC0_mm) const;
	/** The simulated scene wire-frame (L, mm) of a view from head centre @p T_C0inW (m). */
	model::WireFrame sceneOf(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
	                         const geometry::HeadAngles& angles, std::mt19937& rng) const;
	/** One recognition in one view; fills every field of the result but views. */
	SearchResult observe(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
	                     const geometry::HeadAngles& angles, std::mt19937& rng,
	                     Timeline& timeline) const;
	/** The whole sweep; stops at the first view that recognises. */
	SearchResult sweep(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
	                   std::mt19937& rng, Timeline& timeline) const;
	const geometry::BiSightHead& head() const { return head_; }
	/** Called with the head angles of every sweep view (e.g. to grab a stereo pair). */
	std::function<void(const geometry::HeadAngles&)> on_view;
	/** A view reconstructed from the head's stereo pair: its scene wire-frame (L, mm) and, when
	 * image verification is on, the pair's edge evidence for recog::Recognizer. */
	struct StereoScene
	{
		model::WireFrame scene;
		std::shared_ptr<const recog::ImageVerifier> images;  ///< null: 3D verification only
	};
	/** When set, a view's scene comes from this instead of sceneOf(). */
	std::function<StereoScene(const geometry::HeadAngles&)> scene_from_stereo;

 private:
	void compareWithTruth(const WorldObjects& objects, const Eigen::Isometry3d& T_C0inW,
	                      SearchResult& r) const;
	const MissionOptions& o_;
	geometry::BiSightHead head_;
	recog::Recognizer recognizer_;
	std::string target_;
	Eigen::Vector3d p_centreinO_mm_;  ///< centre of the target's wire-frame
	const std::map<std::string, model::WireFrame>& models_;
};

}  // namespace mrolr::mission
