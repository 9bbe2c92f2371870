#pragma once
/** Options of the pose hypotheses made from single scene features on the support plane
 * (PlaneHypotheses.h), section [plane_hypotheses] of config/recognition.ini. */

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>

namespace mrolr::recog
{
/** When the support-plane hypotheses run: "always" after the clique levels, the better-ranked
 * answer kept (a plane hypothesis can correct a clique's wrong yaw of a nearly symmetric object);
 * "not_found": only when the levels found nothing. */
enum class PlaneRunWhen
{
	Always,
	NotFound
};

/** Section [plane_hypotheses] of config/recognition.ini. The section is optional (without it
 * these defaults); when present every key must be there. */
struct PlaneHypothesisOptions
{
	bool enable = true;  ///< make plane hypotheses (only with images and a support plane)
	PlaneRunWhen run_when = PlaneRunWhen::Always;  ///< key run_when: always | not_found
	double rim_normal_tol_deg = 15;    ///< a model rim's normal within this of the model's +z
	double scene_normal_tol_deg = 20;  ///< a scene conic's normal within this of the plane's
	double radius_tol_mm = 6;          ///< |scene mean semi-axis − model rim radius|
	double height_tol_mm = 10;         ///< |feature height above the plane − model height|
	double horizontal_tol_deg = 10;    ///< model and scene lines this close to horizontal
	double max_length_ratio = 1.2;     ///< a scene line at most this × the model line's length
	double min_line_mm = 15;           ///< shorter model or scene lines are not used
	/** Yaws tried per rim or limb match (the refinement sweeps finer). */
	double rim_yaw_step_deg = 30;
	/** Limb hypotheses (PlaneHypotheses.h). These four keys are optional in the section (files
	 * written before them still load); defaults as here. */
	bool limb_hypotheses = true;
	double limb_vertical_tol_deg = 5;  ///< a scene line this close to the plane's normal
	double limb_max_taper_mm = 3;      ///< a model frustum with |r0 − r1| up to this is a cylinder
	double limb_min_mm = 20;           ///< shorter scene lines and model cylinders are not used
	/** Edge-pair hypotheses (PlaneHypotheses.h), for models without cylinders: two scene lines
	 * along the plane's normal (as limbs: limb_vertical_tol_deg, limb_min_mm) as far apart as
	 * two of the model's vertical edges at least edge_pair_min_mm long, within
	 * edge_pair_width_tol_mm. Optional keys; defaults as here. */
	bool edge_pair_hypotheses = true;
	double edge_pair_min_mm = 50;
	double edge_pair_width_tol_mm = 4;
	/** Image score an answer from an edge pair needs (at least min_image_score is needed in any
	 * case): two vertical lines so far apart are common among boxes and cylinders. */
	double edge_pair_min_image_score = 0.7;
	/** Hypotheses kept after the quick image score (best first, near-duplicates dropped), then
	 * scored fully and the best refined as the clique hypotheses are. */
	int max_hypotheses = 30;
	double prerank_spacing_mm = 9;  ///< model edge sample spacing of the quick image score
	/** Image score a plane hypothesis needs to be accepted; at least the image verification's
	 * min_score is needed in any case. */
	double min_image_score = 0.65;
	/** After refinement in the images the model's base must still be within this of the plane
	 * (mm); the refinement is free in 6 parameters. */
	double max_base_offset_mm = 15;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::recog
