#pragma once
/** The seven matching parameters of thesis 6.3.2 / paper 3.2 and their fine-to-coarse schedule of
 * thesis 6.4 (12 levels by default), read from config/recognition.ini. */

#include <mrolr/recog/plane/PlaneHypothesisOptions.h>

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>
#include <vector>

namespace mrolr::recog
{
/** One confidence level of the search: the seven parameters (a)–(g) plus the verification
 * threshold that keeps coarse levels from accepting wrong matches. */
struct LevelParams
{
	int clique_size = 4;              ///< (a) minimum matched features in a clique, focus included
	double position_error_mm = 3;     ///< (b) beta: allowed error on a feature's position (mm)
	double rotation_deg = 2;          ///< (c) theta: allowed error on a feature's direction (deg)
	double length_threshold_mm = 10;  ///< (d) scene segments shorter than this are ignored (mm)
	double max_rotation_deg = 4;      ///< (e) clique transforms closer than this agree (deg)
	double max_translation_mm = 8;    ///< (f) clique transforms closer than this agree (mm)
	double length_ratio = 0.5;      ///< (g) focus match: scene length / model length at least this
	double verify_min_score = 0.3;  ///< supported fraction of the model needed to accept, [0,1]
};

/** The pose estimator of clique hypotheses (key pose_method). */
enum class PoseMethod
{
	FaugerasHebert,  ///< faugeras_hebert: the thesis's estimator (PoseEstimation.h)
	Arun,            ///< arun: OpenGV's point-based estimator
	Both             ///< both: one hypothesis from each
};

/** Options of the Recognizer (section [recognition] of config/recognition.ini). */
struct RecognitionOptions
{
	/** The levels, finest first; the search stops at the first level that recognises. */
	std::vector<LevelParams> levels;
	PoseMethod pose_method = PoseMethod::FaugerasHebert;
	/** Automatic cliques for models without any: "recog" (nearest features of the longest ones)
	 * or "model" (model::addAutomaticCliques, viewing-direction coverage). */
	std::string auto_cliques = "recog";
	/** A model file's own `clique` lines: "use" them (alone), "add" the automatic ones to them, or
	 * "ignore" them (automatic ones only). Optional key, default "use". */
	std::string file_cliques = "use";
	/** The same when the hypotheses are verified in images (Recognizer::recognize with an
	 * ImageVerifier). Optional key, default "add": the files' cliques alone missed boxes whose
	 * edges the scene held, and the image score keeps the extra hypotheses' wrong poses out (in
	 * 3D only, "add" let one absent model in on the rendered set of seed 101). */
	std::string file_cliques_with_images = "add";
	int auto_clique_count = 12;   ///< cliques chosen automatically when a model has none
	int auto_clique_size = 7;     ///< features per automatic clique, focus included
	int max_search_nodes = 4000;  ///< budget of the maximal-consistent-set search per focus match
	int refine_iterations = 2;    ///< least-squares refinements on the verified correspondences
	/** Verification tolerances (the whole model carried into the scene): a scene feature supports
	 * a model feature within min(2 beta, verify_position_error_mm) and min(2 theta,
	 * verify_rotation_deg). Capped so that coarse matching levels do not loosen verification. */
	double verify_position_error_mm = 3;
	double verify_rotation_deg = 3;
	int verify_clusters = 20;  ///< heaviest clusters of clique transforms verified per level
	int confirm_levels = 1;    ///< levels run after the first recognition; the best answer is kept
	/** Skip a level whose SupportBound (no pose can reach its verify_min_score) says it cannot
	 * verify: the answer is unchanged, an absent model costs less. Optional key, default true. */
	bool skip_hopeless_levels = true;
	/** When the scene's up direction is given (Recognizer::recognize's up_S), a pose whose model
	 * +z axis (the object frame's up, thesis 6.1 / docs/model.md) is more than this far from it is
	 * rejected: objects stand on the table. 180 turns the prior off. Optional key, default 20.
	 * (deg) */
	double upright_max_tilt_deg = 20;
	/** With an up direction and the upright prior: score a pose by the support of the model
	 * length expected visible from the camera (the scene frame's origin), each feature weighted by
	 * its fraction not hidden by the object's own solid (SelfOcclusion.h), instead of the whole
	 * model's length. Without a prior it is not used: a pose turned over whose expected-visible
	 * part happens to be supported could score 1. Optional key, default true. */
	bool verify_visible_only = true;
	/** verify_min_score is multiplied by this when the visible-only score is used (such scores
	 * are about twice the whole-model ones). Optional key, default 1.2. */
	double visible_min_score_factor = 1.2;
	/** Ambiguity (beyond the thesis): another verified pose of the recognising level whose rank is
	 * within this fraction of the best's, turned at least ambiguity_min_turn_deg from it, and not
	 * a symmetry of the model (fewer than ambiguity_symmetry_share of its edge samples land within
	 * ambiguity_symmetry_mm of the best pose's), makes the answer ambiguous. Optional keys,
	 * defaults 0.05, 20, 3, 0.9. */
	double ambiguity_margin = 0.05;
	double ambiguity_min_turn_deg = 20;
	double ambiguity_symmetry_mm = 3;
	double ambiguity_symmetry_share = 0.9;
	/** Hypotheses from single features on the support plane: section [plane_hypotheses], read
	 * by its own loadFromConfigFile (not by this struct's, which reads [recognition] only). */
	PlaneHypothesisOptions plane;

	/** Twelve levels from fine to coarse (the values shipped in config/recognition.ini). */
	static RecognitionOptions defaults();

	/** Reads the keys of @p section; each per-level key holds `levels` numbers. Throws
	 * util::ConfigError naming file, section and key for missing or bad values. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

	/** Writes the options as `key = values` lines. */
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::recog
