#pragma once
/** Object models from turntable views integrated by recognition (thesis 6.5, "Model Creation (An
 * Alternative Method)"): the first view's scene model, moved into the turntable frame with the
 * calibrated camera-to-turntable transform, is the seed; every further view, moved into the
 * turntable frame the same way but NOT turned by its known angle, is registered to the model
 * accumulated so far by the recogniser (recog::Recognizer), and integrated as the turntable path
 * does (model::mergeDuplicates, model::dropUnsupported, model::renumber).
 *
 * Roles (AlignOptions::match): by default the accumulated model is the recogniser's "model" and
 * the new view, in its left camera frame, the "scene", exactly as an object is recognised in a
 * scene, with the hypotheses judged in the view's stereo images; or, in 3D only, the shorter of
 * the two is the model (see AlignOptions::match for why).
 *
 * Lives in the apps area because the model area may not depend on recog (docs DESIGN.md). The
 * known turntable angles are used only to report each registration's error. Millimetres. */

#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <memory>
#include <ostream>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
/** Options of the alignment ([align] section of config/model.ini). */
struct AlignOptions
{
	/** The recogniser's options: this .ini file (relative to the project) and section. */
	std::string recognition_config = "config/recognition.ini";
	std::string recognition_section = "recognition";
	std::string image_section = "image_verification";  ///< of recognition_config, match = images
	/** Use the turntable frame's +z as the scene's up direction: poses tilting the view's +z
	 * more than the recogniser's upright_max_tilt_deg are rejected (the table is calibrated). */
	bool upright_prior = true;
	/** Passes over the views: a view that fails is tried again after the others have grown the
	 * model (1 = each view once, in order). */
	int passes = 2;
	/** The view that seeds the model (0: the first, as thesis 6.5's reference view). */
	int seed_view = 0;
	/** How a view is matched to the model so far:
	 * - "images": the accumulated model is the recogniser's model, the new view (in its left
	 *   camera frame) its scene, and hypotheses are judged in the view's stereo images
	 *   (recog::ImageVerifier, [image_verification] of recognition_config), whose yaw sweep
	 *   tells near-symmetric poses apart;
	 * - "shorter": 3D only; the shorter of the two wire-frames is the recogniser's model, the
	 *   longer its scene (the verified score is the supported fraction of the model, and the part
	 *   the two share is a larger fraction of the shorter one). */
	std::string match = "images";

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The recogniser's options for registering views, read as @p o says. With match = "shorter"
 * the expected-visible verification is off: it assumes a camera at the scene's origin, and the
 * scene may be the accumulated model. */
recog::RecognitionOptions alignmentRecognitionOptions(const AlignOptions& o);

/** The image verification options (match = "images"), read as @p o says. */
recog::ImageVerificationOptions imageOptions(const AlignOptions& o);

/** One view as the alignment sees it. */
struct AlignView
{
	model::WireFrame wf_T;  ///< reconstructed, cropped, in the turntable frame (not turned)
	/** Its stereo pair (match = "images"); null otherwise. */
	std::shared_ptr<const recog::ImageVerifier> images;
};

/** What registration needs besides the views. */
struct AlignContext
{
	recog::RecognitionOptions recognition;
	AlignOptions align;
	model::TurntableOptions turntable;
	Eigen::Isometry3d T_LinT_mm = Eigen::Isometry3d::Identity();  ///< p_T = T_LinT_mm · p_L
};

/** How one view was registered (frame M: the model, i.e. the object frame O of the first view). */
struct ViewRegistration
{
	size_t view = 0;             ///< index in the turntable set
	double known_angle_deg = 0;  ///< the turntable angle (for the error only)
	bool registered = false;
	std::string reason;   ///< why not registered (empty when registered)
	int pass = 0;         ///< 1-based pass that registered it (0: the seed or not registered)
	size_t features = 0;  ///< lines and conics of the view after cropping
	Eigen::Isometry3d T_VinM = Eigen::Isometry3d::Identity();  ///< view (turntable frame) → M
	/** The recovered turntable angle (deg): −(turn about +z of T_VinM), as p_T = Rz(angle) · p_O;
	 * decides which views are near each other in the integration (model::integrateViews). */
	double turn_deg = 0;
	bool view_is_model = false;  ///< the view was the recogniser's model (else its scene)
	double score = 0;            ///< recogniser's verified score
	std::optional<int> level;    ///< the recogniser's clique level (1-based) when registered
	/** Error against the known angle, modulo the object's symmetry: rotation angle (deg) and
	 * displacement of the view's centroid (mm) of S⁻¹ · T_VinM · T_trueᵀ, T_true = Rz(−angle) and
	 * S the turn by symmetry_deg. */
	double rot_err_deg = 0, trans_err_mm = 0;
	/** Turn about O's +z (deg) that maps the exact model onto itself and brings the recovered
	 * pose nearest to the true one (a box turned by 180°, any turn for a body of revolution);
	 * the integrated model is the same as with the true pose. 0 without symmetry or truth. */
	double symmetry_deg = 0;
};

/** The built model and every view's registration. */
struct AlignmentResult
{
	model::WireFrame model;  ///< frame object, ids renumbered, no cliques
	std::vector<ViewRegistration> views;
	size_t registered = 0;
};

/** Registers @p views to the seed view views[c.align.seed_view] turned by −@p seed_angle_deg
 * into O (the seed's known angle only names the object frame). Throws std::invalid_argument when
 * the seed does not exist or has fewer than two features. Views that fail are reported, never
 * merged. */
std::vector<ViewRegistration> registerViews(const std::vector<AlignView>& views,
                                            double seed_angle_deg, const AlignContext& c);

/** One attempt to register @p view (features in r.features) to the model so far @p acc_M
 * (frame M = O, ids unique): sets r.registered, r.reason, r.T_VinM, r.score, r.level. */
void matchView(ViewRegistration& r, const AlignView& view, const model::WireFrame& acc_M,
               const AlignContext& c);

/** The whole thesis 6.5 build: reconstructs every view of @p set, registers them and integrates
 * the registered ones. @p truth (optional, frame O) tells symmetric registrations apart. */
AlignmentResult buildByRecognition(const model::TurntableSet& set, const stereo::SceneOptions& so,
                                   const model::TurntableOptions& to, const AlignOptions& ao,
                                   const model::WireFrame* truth = nullptr);

/** Fills the error fields of @p r (registered, known_angle_deg set) against the true
 * T_VinM = Rz(−known_angle_deg) (p_T = Rz(angle) · p_O, docs/model.md); @p view_T gives the
 * centroid, @p truth (frame O, may be null) the symmetries (a turn S about +z is one when the
 * truth carried by S lies within 1 mm of itself). */
void measureRegistrationError(ViewRegistration& r, const model::WireFrame& view_T,
                              const model::WireFrame* truth);

}  // namespace mrolr::apps
