#pragma once
/** The options of the verification in the stereo images (ImageVerifier.h): section
 * [image_verification] of config/recognition.ini. */

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <string>

namespace mrolr::recog
{
/** Section [image_verification] of config/recognition.ini. */
struct ImageVerificationOptions
{
	double blur_sigma_px = 1.0;  ///< Gaussian blur before Canny (px; 0: none)
	double canny_low = 20;       ///< Canny hysteresis thresholds (grey levels, L2 gradient)
	double canny_high = 50;
	double edge_distance_px = 2.0;    ///< a sample is supported within this of an edge pixel (px)
	double orientation_tol_deg = 20;  ///< ... whose edge direction is within this of its own
	double sample_spacing_mm = 3;     ///< model edges sampled every this many mm
	int min_samples = 30;             ///< fewer expected-visible samples in view: score 0
	double min_score = 0.65;          ///< image score needed to accept a hypothesis, [0, 1]
	/** 3D verification score (expected-visible when the up direction is known) a hypothesis
	 * needs before the images are asked: with images the 3D score is only a pre-filter. */
	double prefilter_score = 0.0;
	/** The best hypotheses of a level (by image score, at least half of min_score) are refined in
	 * the images: rotations about the model's up axis (z through its rims' centres) every
	 * yaw_step_deg (0: none; a cup's handle is what fixes its yaw), then Levenberg–Marquardt
	 * over the 6 pose parameters on the samples' distances to the edge lines, each step kept only
	 * if it lowers the truncated oriented chamfer distance (ImageVerifier::edgeLineSearch). */
	int refine_candidates = 6;
	double yaw_step_deg = 5;
	/** chamfer distance cap (px); also the cost of a wrongly oriented edge, and the farthest an
	 * edge may be to give a sample an edge-line residual */
	double truncate_px = 5;
	/** Add, at each pose and for each camera, the limbs (outline generators) of the model's
	 * bodies of revolution (SelfOcclusion::revolutionBodies, Limbs.h) to the samples judged;
	 * docs/recog-limbs.md. */
	bool limbs = true;
	/** Judge the self-occlusion of samples on a body of revolution against its exact solid
	 * (SelfOcclusion::hiddenOnBodies) instead of the convex polytope (SelfOcclusion::hidden). */
	bool revolution_visibility = true;
	/** Mutual occlusion (docs/recog.md): samples behind an object already recognised in the same
	 * images (inside its projected outline and more than occluder_margin_mm deeper than its
	 * centre) are neither supported nor unsupported; a pose with less than
	 * min_unoccluded_fraction of its in-view samples left scores 0. */
	double occluder_margin_mm = 10;
	double min_unoccluded_fraction = 0.5;
	/** Search again, with the found objects as occluders, for the models not found (the callers
	 * that recognise several models in one stereo pair: mrolr-recognize, its evaluation). */
	bool mutual_occlusion = true;
	/** A pose with less than this fraction of its samples not hidden by the object itself inside
	 * the images (both summed) scores 0: a few edges of an object standing mostly outside the
	 * view fit clutter at the image border too easily. */
	double min_in_image_fraction = 0.5;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::recog
