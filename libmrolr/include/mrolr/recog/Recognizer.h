#pragma once
/** Recognition of one object model in scene wire-frames (thesis 6.3–6.4, paper 3.2–3.3): clique
 * matching, Faugeras–Hebert (and/or OpenGV Arun) poses, clustering of agreeing clique transforms,
 * verification of the whole model in the scene, all repeated over the fine-to-coarse levels until
 * recognition; and the search over the scene models of a pan sweep. Unlike the thesis, every
 * answer carries a confidence and an absent object is reported as not found. */

#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/recog/SupportBound.h>
#include <mrolr/recog/TransformCluster.h>
#include <mrolr/recog/Verification.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/RefineMemo.h>
#include <mrolr/recog/plane/PlaneHypotheses.h>
#include <mrolr/recog/plane/SupportPlane.h>

#include <Eigen/Geometry>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::recog
{
/** A pose the scene supports, and how well (the rank the answer was chosen by: image score +
 * 0.05 × 3D score with images, 3D score + 0.05 × coverage without). */
struct PoseSupport
{
	Eigen::Isometry3d T_OinS = Eigen::Isometry3d::Identity();
	double support = 0;
};

/** Where an answer (or, when nothing was found, the best candidate) came from. */
enum class Origin
{
	None,         ///< no hypothesis was verified
	Clique,       ///< a cluster of clique transforms at one of the levels (thesis 6.3)
	SupportPlane  ///< a single scene feature on the support plane (PlaneHypotheses.h)
};

/** "none", "clique" or "support_plane", for reports. */
const char* originName(Origin origin);

/** The confidence of a clique answer: its score (the image score when verified in images) ×
 * (1 − 0.5 (level − 1)/(levels − 1)), level 1-based: a coarser level accepts looser matches. */
double cliqueConfidence(double score, int level, size_t levels);
/** The confidence of a support-plane answer: half its image score. One scene feature made the
 * hypothesis, where a clique answer rests on several that agree. */
double planeConfidence(double image_score);

/** Where one recognition spent its time: wall ms of each stage, summed over the levels and the
 * support-plane search (RecognitionResult::ms also holds what is in none of them). */
struct RecognitionTimes
{
	double cliques_ms = 0;       ///< clique matching, poses and their clustering (thesis 6.3)
	double verify_3d_ms = 0;     ///< verification in the scene wire-frame (thesis 6.4)
	double image_score_ms = 0;   ///< image scores of the verified poses (ImageVerifier::score)
	double image_refine_ms = 0;  ///< refinement in the images and the scores after it
	double plane_ms = 0;         ///< support-plane hypotheses and their quick image pre-rank

	RecognitionTimes& operator+=(const RecognitionTimes& o);
	RecognitionTimes scaled(double f) const;  ///< every stage times f
	double total_ms() const;
};

struct RecognitionResult
{
	std::string model;
	bool found = false;
	Origin origin = Origin::None;
	Eigen::Isometry3d T_OinS = Eigen::Isometry3d::Identity();  ///< model → scene frame (mm)
	double score = 0;     ///< verified fraction of the model's length supported by the scene
	double coverage = 0;  ///< supported length / length of the model features with support
	int matched = 0;      ///< model features supported in the scene
	/** The 1-based level whose clique recognised; empty when not found or from the plane. */
	std::optional<int> level;
	/** cliqueConfidence() or planeConfidence() of a found answer; 0 when not found. */
	double confidence = 0;
	int agreeing_cliques = 0;        ///< clique transforms in the winning cluster
	double spread_rot_deg = 0;       ///< RMS spread of those transforms (deg)
	double spread_trans_mm = 0;      ///< RMS spread of the carried model centroid (mm)
	std::optional<int> scene_index;  ///< which scene of a sweep held it (searchSweep, found)
	double ms = 0;                   ///< wall time of the search (ms)
	RecognitionTimes times;          ///< where ms went
	int levels_skipped = 0;          ///< levels skipped: SupportBound says they cannot verify
	/** With images: the refinements in the images the search made (ImageVerifier::refine), and
	 * the candidates that took the result of one of them instead, starting within 2 mm and 2° of
	 * where it started or ended (levels and plane hypotheses find the same pose again). */
	int image_refinements = 0, image_refinements_reused = 0;
	/** Of those made, the yaw sweeps taken from an earlier one's circle (RefineMemo). */
	int image_sweeps_reused = 0;
	/** With images (ImageVerifier): the image score of the pose (fraction of the expected-visible
	 * model edge samples on image edges), which decided acceptance; empty without images. */
	std::optional<double> image_score;
	/** Found in the second search of mutual occlusion (MutualOcclusion.h): this many recognised
	 * objects' regions were left out of the image score. 0: found without them. */
	int occluders = 0;
	/** Several poses supported about equally (RecognitionOptions::ambiguity_*): a nearly
	 * symmetric object whose telling part is hidden. poses then lists every one of them, the
	 * best (T_OinS) first; empty when not ambiguous. */
	bool ambiguous = false;
	std::vector<PoseSupport> poses;
};

/** What is known of a scene besides its features; each part is optional.
 * - up_S: the scene's up direction (unit, scene frame); poses tilted more than
 *   RecognitionOptions::upright_max_tilt_deg from it are rejected. Without it a support plane's
 *   normal is the up direction.
 * - images: the stereo pair the scene was reconstructed from (scene frame = left camera L). With
 *   it the 3D score is only a pre-filter (ImageVerificationOptions::prefilter_score) and a
 *   hypothesis is accepted, and ranked, by its image score (min_score); the scene's features
 *   still generate the hypotheses.
 * - plane: the support plane the objects stand on (scene frame). With images and
 *   RecognitionOptions::plane.enable, single scene features on it make further hypotheses
 *   (Recognizer::recognizeOnPlane) after the levels, the better-ranked answer kept.
 * - repeat: the scene is the one this Recognizer searched last, with the same up direction, now
 *   with other images (the second search of mutual occlusion, MutualOcclusion.h): each level's
 *   clusters and 3D-verified poses are taken from that search instead of being computed again.
 *   The images change neither. If the scene or the up direction differs, nothing is reused. */
struct SceneContext
{
	std::optional<Eigen::Vector3d> up_S;
	std::optional<std::reference_wrapper<const ImageVerifier>> images;
	std::optional<SupportPlane> plane;
	bool repeat = false;

	/** The up direction in force: up_S, else the plane's normal, else none. */
	std::optional<Eigen::Vector3d> up() const;
};

class Recognizer
{
 public:
	/** Builds the model's pairwise tables and cliques once. Throws std::invalid_argument for a
	 * model that cannot be matched (fewer than two features, degenerate elements, bad cliques). */
	Recognizer(const model::WireFrame& model, const RecognitionOptions& opts);

	/** Runs the levels fine to coarse on one scene; after the first level that recognises, runs
	 * options().confirm_levels more and keeps the best-ranked answer (a coarser level can find the
	 * clique that a nearly symmetric object's true pose needs). With skip_hopeless_levels, levels
	 * whose verify_min_score no pose can reach (SupportBound, computed once) are not run. Then,
	 * with images and a plane in @p context, the support-plane hypotheses
	 * (options().plane.run_when: always, or only when the levels found nothing). */
	RecognitionResult recognize(const std::vector<Feature>& scene,
	                            const SceneContext& context = {}) const;
	RecognitionResult recognize(const model::WireFrame& scene,
	                            const SceneContext& context = {}) const;

	/** Hypotheses from single scene features on @p plane (PlaneHypothesisGenerator), ranked by a
	 * quick image score (options().plane.prerank_spacing_mm), the best options().plane
	 * .max_hypotheses scored and refined in @p images as the clique hypotheses are; found when
	 * the best reaches options().plane.min_image_score (and the images' min_score) with its base
	 * within max_base_offset_mm of the plane. */
	RecognitionResult recognizeOnPlane(const std::vector<Feature>& scene, const SupportPlane& plane,
	                                   const ImageVerifier& images) const;
	const PlaneHypothesisGenerator& planeGenerator() const { return *plane_gen_; }

	/** Focus-match bounds (mm) of one scene, by (model focus, scene feature), and the clique
	 * members' candidates (MemberCandidates), computed for the coarsest tolerances of all levels
	 * so that every level can use them. */
	struct FocusBounds
	{
		std::shared_ptr<SupportBound> bound;
		double match_beta_mm = 0;
		std::map<std::pair<size_t, size_t>, double> mm;
		/** The clique members' candidates under the levels' loosest tolerance (with images). */
		std::shared_ptr<MemberCandidates> members;
	};

	/** One level (0-based) on one scene; found when the best verified cluster reaches the level's
	 * verify_min_score. @p bounds: focus bounds shared between the levels of one scene (start
	 * with an empty one); @p context's up direction and images as in recognize() (not its plane).
	 */
	RecognitionResult recognizeAtLevel(const std::vector<Feature>& scene, size_t level,
	                                   FocusBounds& bounds, const SceneContext& context) const;

	/** Thesis 6.4: scene models of a pan sweep in order; the first scene where the object is
	 * recognised ends the search. */
	RecognitionResult searchSweep(const std::vector<model::WireFrame>& scenes) const;

	/** True when no up direction is given or the pose's model +z is within
	 * options().upright_max_tilt_deg of @p up_S. */
	bool upright(const Eigen::Isometry3d& T_OinS, const std::optional<Eigen::Vector3d>& up_S) const
	{
		return upright(T_OinS, up_S ? &*up_S : nullptr);
	}

	/** SupportBound of the scene for the most permissive verification tolerances of all levels
	 * (mm of model length). */
	double supportBound_mm(const std::vector<Feature>& scene) const;
	/** Model length counted by verification at @p level (features >= its length threshold). */
	double modelLength_mm(size_t level) const;
	/** The supported model length a pose needs at @p level to pass verification (mm): its minimum
	 * score (minScore) times the expected-visible share times modelLength_mm. With images and
	 * their default pre-filter score (0) it is 0: no support bound can rule anything out then. */
	double supportNeeded_mm(size_t level, const Eigen::Vector3d* up_S,
	                        const ImageVerifier* images) const;

	const ModelTable& table() const { return table_; }
	/** The table whose cliques generate hypotheses with (@p images true) or without images. */
	const ModelTable& tableFor(bool images) const
	{
		return images && image_table_ ? *image_table_ : table_;
	}
	/** The model's edges sampled every @p spacing_mm for image verification (arcs as they are). */
	std::vector<EdgeSample> edgeSamples(double spacing_mm) const
	{
		return edgeSamplesOf(model_, spacing_mm);
	}
	/** edgeSamples(@p spacing_mm) with their sight against selfOcclusion(): built on the first
	 * call for each spacing and kept (thread-safe; shared by copies of this Recognizer). */
	const SightedSamples& sightedSamples(double spacing_mm) const;
	/** The self-occlusion the 3D verification uses with the scene up direction @p up_S: the
	 * model's when options().verify_visible_only and an upright prior is set, else none. */
	const SelfOcclusion* occlusion(const std::optional<Eigen::Vector3d>& up_S) const
	{
		return occlusionFor(up_S ? &*up_S : nullptr);
	}
	/** The model's self-occlusion, always built: image verification hides the back edges with it
	 * whether or not the 3D score does. */
	const SelfOcclusion& selfOcclusion() const { return *occlusion_; }
	const RecognitionOptions& options() const { return opts_; }

 private:
	/** A hypothesis's pose after 3D verification, and its image score once judged in images. */
	struct VerifiedPose
	{
		Eigen::Isometry3d T;
		VerificationResult v;
		std::optional<double> image;
		size_t hypothesis = 0;    ///< the clique cluster or plane hypothesis it came from
		ImageScore image_counts;  ///< the counts and cost behind image: a refinement's start
	};
	/** The refinements in the images made in one search (recognize(): its levels and its plane
	 * hypotheses share them): where each started and where it ended. */
	struct Refinements
	{
		struct Made
		{
			Eigen::Isometry3d start;
			ScoredPose result;
		};
		std::vector<Made> made;
		int reused = 0;   ///< candidates given the result of one of made
		RefineMemo memo;  ///< what made swept and searched
	};
	// Internally an absent up direction or image pair is a null pointer.
	bool upright(const Eigen::Isometry3d& T_OinS, const Eigen::Vector3d* up_S) const;
	RecognitionResult atLevel(const std::vector<Feature>& scene, size_t level, FocusBounds& bounds,
	                          const Eigen::Vector3d* up_S, const ImageVerifier* images, bool repeat,
	                          Refinements& refined) const;
	/** recognizeOnPlane() sharing @p refined with the levels of the same search. */
	RecognitionResult onPlane(const std::vector<Feature>& scene, const SupportPlane& plane,
	                          const ImageVerifier& images, Refinements& refined) const;
	/** Marks @p best ambiguous when another of @p poses is a near-equal rival (not a symmetry). */
	void markAmbiguity(RecognitionResult& best, const std::vector<VerifiedPose>& poses) const;
	/** True when the model's edges under @p a and @p b coincide within ambiguity_symmetry_mm. */
	bool symmetric(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) const;
	/** Scores @p poses in @p images, refines the best options().refine_candidates in the images
	 * (ImageVerifier::refine) and re-verifies them in 3D against @p scene at level @p p. A pose
	 * that starts where one of @p refined started or ended (kSameStart) takes its result. */
	void judgeInImages(std::vector<VerifiedPose>& poses, const ImageVerifier& images,
	                   const std::vector<Feature>& scene, const LevelParams& p,
	                   const Eigen::Vector3d* up_S, Refinements& refined,
	                   RecognitionTimes& times) const;
	/** ImageVerifier::refine of @p start (a pose in S and its score), or the result of an entry
	 * of @p refined that started or ended within kSameStart of it; a new refinement is added to
	 * @p refined. */
	ScoredPose refinedOnce(const ImageVerifier& images, const SightedSamples& samples,
	                       const ScoredPose& start, const std::vector<Eigen::Vector3d>& axes_O,
	                       Refinements& refined) const;

	/** Skips focus matches whose SupportBound::focusSupportBound_mm cannot reach the level's
	 * verify_min_score (empty unless skip_hopeless_levels, and when nothing is needed: a bound is
	 * a length, never below 0). */
	FocusFilter focusFilter(const std::vector<Feature>& scene, const OrientedScene& os,
	                        size_t level, FocusBounds& bounds, const Eigen::Vector3d* up_S,
	                        const ImageVerifier* images) const;
	/** The self-occlusion verification uses: only with an up direction and an upright prior
	 * (without them a pose turned over, whose expected-visible part happens to be supported, can
	 * score 1). */
	const SelfOcclusion* occlusionFor(const Eigen::Vector3d* up_S) const;
	/** min_visible_share_ when occlusionFor(up_S), else 1. */
	double visibleShare(const Eigen::Vector3d* up_S) const;
	/** The score @p level needs: verify_min_score, times visible_min_score_factor when the
	 * visible-only score is used. */
	double minScore(size_t level, const Eigen::Vector3d* up_S,
	                const ImageVerifier* images = nullptr) const;

	ModelTable table_;
	/** The table whose cliques are used with images (options().file_cliques_with_images); null
	 * when it equals file_cliques (table_ then serves). */
	std::shared_ptr<const ModelTable> image_table_;
	model::WireFrame model_;  ///< as given: image verification samples its arcs
	RecognitionOptions opts_;
	Eigen::Vector3d centroid_O_;
	std::shared_ptr<const SelfOcclusion> occlusion_;
	/** Lower bound of the expected-visible share of the model length over viewpoints (1 without
	 * occlusion): scales the support a level needs when skipping hopeless levels. */
	double min_visible_share_ = 1.0;
	std::shared_ptr<const PlaneHypothesisGenerator> plane_gen_;
	struct SampleCache;
	static std::shared_ptr<SampleCache> newSampleCache();
	std::shared_ptr<SampleCache> samples_;  ///< sightedSamples() per spacing

	/** What a level made of a scene before the images judged it: the clusters of clique poses
	 * and the poses verified in 3D. */
	struct LevelHypotheses
	{
		std::vector<PoseCluster> clusters;
		std::vector<VerifiedPose> verified;
	};
	/** The clusters and verified poses of @p level on @p scene, computed (and kept) or, with
	 * @p repeat (SceneContext::repeat) and when the last scene searched had the same features,
	 * up direction and image use, as computed then. The images change neither (only whether the
	 * 3D pre-filter applies). */
	LevelHypotheses levelHypotheses(const std::vector<Feature>& scene, const OrientedScene& os,
	                                size_t level, FocusBounds& bounds, const Eigen::Vector3d* up_S,
	                                const ImageVerifier* images, bool repeat,
	                                RecognitionTimes& times) const;
	LevelHypotheses computeLevelHypotheses(const std::vector<Feature>& scene,
	                                       const OrientedScene& os, size_t level,
	                                       FocusBounds& bounds, const Eigen::Vector3d* up_S,
	                                       const ImageVerifier* images,
	                                       RecognitionTimes& times) const;
	struct LevelCache;
	static std::shared_ptr<LevelCache> newLevelCache();
	std::shared_ptr<LevelCache> levels_cache_;  ///< the last scene's LevelHypotheses
};

}  // namespace mrolr::recog
