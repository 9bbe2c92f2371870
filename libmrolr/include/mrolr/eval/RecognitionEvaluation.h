#pragma once
/** Evaluation of object recognition on rendered table scenes: the simulator renders the
 * lab table with a few of the lab objects at random positions and yaws, seen from random vehicle
 * poses with the head fixating the table (so the objects are seen under different tilts, partly
 * hidden by each other); stereo::reconstructScene turns each pair into a scene wire-frame in the
 * left camera frame L; every model of the database is then searched in every scene and compared
 * with the simulator's truth. Everything is deterministic for a seed, so the set is fixed.
 * (The world side's truth meets the recogniser's answers only here, after the searches.) */

#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/GroundTruth.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/math/CMatrixF.h>
#include <opencv2/core.hpp>

#include <Eigen/Geometry>

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::eval
{
/** Section [evaluation] of config/recognition.ini. */
struct EvaluationOptions
{
	std::string world = "maps/lab/world.ini";  ///< lab (room, table); its objects are replaced
	std::string table = "main";                ///< the table the objects stand on
	int scenes = 12;                           ///< rendered scenes in the set
	unsigned seed = 1;                         ///< scene k uses seed + k
	int min_objects = 3, max_objects = 4;      ///< objects per scene
	double cluster_radius_m = 0.2;             ///< objects within this of the fixated table point
	double object_gap_m = 0.02;                ///< clearance between object footprints
	double min_view_distance_m = 0.65;         ///< horizontal distance C0 → fixated point
	double max_view_distance_m = 0.95;
	double fixation_height_m = 0.05;     ///< fixated point above the table top
	double min_visible_fraction = 0.5;   ///< cases counted in the recognition rate
	double visibility_depth_tol_mm = 6;  ///< an edge point is visible when not this far behind
	double max_rotation_error_deg = 10;  ///< a found pose closer than these is correct
	double max_translation_error_mm = 30;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One object in a rendered scene. */
struct EvalObject
{
	std::string model;                                         ///< object definition name
	Eigen::Isometry3d T_OinL = Eigen::Isometry3d::Identity();  ///< truth, mm, thesis L axes
	double visible_fraction = 0;  ///< visible length of its true edges / their total length
};

/** One rendered and reconstructed scene. */
struct EvalScene
{
	int index = 0;
	cv::Mat left, right;              ///< 8-bit grey, as rendered
	stereo::StereoCalibration calib;  ///< the head's ideal cameras at the scene's angles
	model::WireFrame scene;           ///< reconstructed, frame left_camera (mm)
	Eigen::Vector3d up_L = Eigen::Vector3d::UnitY();  ///< the room's up in L (from the head angles)
	/** The table top in L (mm; normal up_L): from the table's height in the world and the
	 * camera's pose. */
	recog::SupportPlane plane_L;
	std::vector<EvalObject> objects;
	double render_s = 0, reconstruct_s = 0;
	const EvalObject* find(const std::string& model) const;
};

/** Renders the scenes of the set (one EGL context; not thread-safe). */
class EvalSceneGenerator
{
 public:
	/** @p shapes: object definitions by model name (the database's objects). */
	EvalSceneGenerator(const EvaluationOptions& opts, const geometry::BiSightHead& head,
	                   const sim::RenderOptions& render, const stereo::SceneOptions& scene,
	                   std::map<std::string, world::ObjectShape> shapes);
	~EvalSceneGenerator();

	/** Scene @p k of the set (deterministic). Throws std::runtime_error when no placement fits. */
	EvalScene make(int k);

	const EvaluationOptions& options() const { return opts_; }
	const std::map<std::string, world::ObjectShape>& shapes() const { return shapes_; }
	/** The exact wire-frame of a model (sim::objectWireFrame), named after it. */
	const model::WireFrame& truthWireFrame(const std::string& model) const;

 private:
	EvaluationOptions opts_;
	geometry::BiSightHead head_;
	stereo::SceneOptions scene_opts_;
	world::World lab_;
	std::map<std::string, world::ObjectShape> shapes_;
	std::map<std::string, model::WireFrame> truth_;
	std::map<std::string, double> radius_m_;  ///< footprint radius of each object (m)
	std::unique_ptr<sim::StereoRenderer> renderer_;
	mrpt::opengl::COpenGLScene::Ptr base_scene_;  ///< the lab without objects

	sim::StereoFrame renderWith(const world::World& w, const Eigen::Isometry3d& T_C0inW,
	                            const geometry::HeadAngles& a, uint64_t frame);
	void reconstruct(EvalScene& s) const;  ///< s.scene from s.left, s.right, s.calib
	EvalObject truthOf(const sim::ObjectView& ov, const stereo::StereoCalibration& calib,
	                   const mrpt::math::CMatrixFloat& depth_m) const;
};

/** Fraction of the length of @p truth_O (object frame, mm) at @p T_OinL that the left camera
 * sees: inside the image and not behind the rendered depth by more than @p depth_tol_mm. */
double visibleFraction(const model::WireFrame& truth_O, const Eigen::Isometry3d& T_OinL,
                       const cv::Matx33d& K_left, const mrpt::math::CMatrixFloat& depth_m,
                       double depth_tol_mm);

/** Rotations about O's z (deg) that map @p truth_O onto itself within 0.5 mm; {-1} stands for
 * every angle (a body of revolution). Always holds 0. */
std::vector<double> symmetryAnglesDeg(const model::WireFrame& truth_O);

/** Rotation error (deg) of @p R_est against @p R_true, minimised over the symmetries. */
double rotationErrorDeg(const Eigen::Matrix3d& R_true, const Eigen::Matrix3d& R_est,
                        const std::vector<double>& symmetry_deg);

/** One model searched in one scene. */
struct EvalCase
{
	int scene = 0;
	std::string model;
	bool present = false;
	double visible_fraction = 0;
	bool found = false, correct = false;         ///< correct: found and within the error limits
	double rot_err_deg = -1, trans_err_mm = -1;  ///< -1 unless present and found
	double score = 0, truth_score = 0;  ///< verified score found / at the true pose (present)
	/** Image score (recog::ImageVerifier) found / at the true pose; empty without images. */
	std::optional<double> image_score, truth_image_score;
	std::optional<int> level;  ///< the clique level that recognised (1-based), as the result's
	int levels_skipped = 0;  ///< levels the support bound skipped
	double score_bound = 0;  ///< SupportBound over the coarsest level's model length
	double ms = 0;
	recog::RecognitionResult result;  ///< the recogniser's answer
};

/** Searches @p rec's model in @p s and compares with the truth (@p symmetry_deg of the model's
 * object, from symmetryAnglesDeg). The search knows the scene's up direction (s.up_L) and what
 * @p context adds: the scene's stereo pair for image verification, its support plane (s.plane_L).
 */
EvalCase evaluateCase(const recog::Recognizer& rec, const EvalScene& s,
                      const std::vector<double>& symmetry_deg, const EvaluationOptions& opts,
                      const recog::SceneContext& context);

/** The figures of a set of cases. */
struct EvalSummary
{
	int rate_cases = 0;             ///< present with visible_fraction >= min_visible_fraction
	int recognised = 0;             ///< of those, found at a correct pose
	int absent_cases = 0;           ///< model absent from the scene
	int false_positives = 0;        ///< absent but found
	int wrong_poses = 0;            ///< present, found at a pose beyond the error limits
	int recognised_from_plane = 0;  ///< of the recognised, by a support-plane hypothesis
	double rate = 0;                ///< recognised / rate_cases
	double median_rot_err_deg = -1, median_trans_err_mm = -1;  ///< over correct rate cases
	double median_ms = 0, max_ms = 0;                          ///< per model and scene, all cases
	double median_absent_ms = 0;                               ///< absent cases
	recog::RecognitionTimes mean_times;  ///< per model and scene, each stage's mean over all cases
};

EvalSummary summarize(const std::vector<EvalCase>& cases, const EvaluationOptions& opts);

/** The generator of the shipped set: the lab of @p opts.world, the head of config/bisight.ini,
 * the render options of config/sim.ini [render] and the scene options of [scene] in the project
 * file @p scene_config. Throws util::ConfigError naming file, section and key. */
std::unique_ptr<EvalSceneGenerator> makeSceneGenerator(
    const EvaluationOptions& opts, const std::string& scene_config = "config/model.ini");

/** The simulator's exact wire-frame of every object of @p gen, in name order. */
std::vector<model::WireFrame> truthModels(const EvalSceneGenerator& gen);

/** The .wf models at @p paths (empty: every .wf of datasets/objects, in path order). Throws
 * std::runtime_error when one is named after no object of @p gen (no truth to compare with). */
std::vector<model::WireFrame> databaseModels(const EvalSceneGenerator& gen,
                                             const std::vector<std::string>& paths);

/** How the models are searched in each scene of the set. */
struct SetSearchOptions
{
	recog::RecognitionOptions recognition;
	/** Verify the hypotheses in the scene's stereo pair (and, with mutual_occlusion, search the
	 * models not found again behind the found ones); unset: verification in 3D only. */
	std::optional<recog::ImageVerificationOptions> images;
};

/** Called after the searches of each scene, in scene order, with what was found there (one result
 * per model, in model order). Scenes are not kept: each holds its stereo pair. */
using SceneObserver =
    std::function<void(const EvalScene& scene, const std::vector<recog::RecognitionResult>& found)>;

/** Renders scenes 0 … gen.options().scenes − 1, searches every model of @p models in each (with
 * the scene's up direction and support plane) and compares with the truth: one case per scene and
 * model, scene by scene in model order. Each model must be an object of @p gen. */
std::vector<EvalCase> evaluateSet(EvalSceneGenerator& gen,
                                  const std::vector<model::WireFrame>& models,
                                  const SetSearchOptions& search,
                                  const SceneObserver& observe = {});

}  // namespace mrolr::eval
