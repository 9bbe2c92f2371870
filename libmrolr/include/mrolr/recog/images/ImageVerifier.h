#pragma once
/** Verification of pose hypotheses in the stereo images (beyond the thesis, which verified in 3D
 * only). A hypothesis T_OinL is judged by projecting the model's expected-visible edges
 * into the left and right images and counting how many of their samples lie on an image edge
 * (Canny) with a compatible orientation: an oriented chamfer test on OpenCV's distance transform.
 * Unlike the 3D score it does not depend on what stereo managed to reconstruct. Millimetres in the
 * thesis's left camera frame L (z along the optic axis, x left, y up); pixels in the original
 * (unrectified) images of the stereo::StereoCalibration. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/recog/images/ImageVerificationOptions.h>
#include <mrolr/recog/images/Limbs.h>
#include <mrolr/recog/images/ProjectedRun.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <opencv2/core.hpp>

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

namespace mrolr::recog
{
/** A point of the model's up axis (z): the mean centre of its conics whose normal is within 25°
 * of z, else the centroid of its features' midpoints (model frame, mm). */
Eigen::Vector3d upAxisPoint(const std::vector<Feature>& features);

/** The vertical axes the image refinement turns a pose about (model frame, mm): upAxisPoint(), and
 * the length-weighted centroid of all features when it is more than 2 mm (horizontally) from it.
 * A box with a conic on one face (a letter O, a straw hole) is turned about its own centre too:
 * about the conic alone its symmetric outline never lands on the edges at the other yaws. */
std::vector<Eigen::Vector3d> upAxisPoints(const std::vector<Feature>& features);

/** Samples every @p spacing_mm along lines and around conics (an ellipse as a circle of its mean
 * semi-axis, as SelfOcclusion does: a Feature keeps neither the major axis nor the arc's ends, so
 * a partial arc is sampled whole); at least 2 per feature. */
std::vector<EdgeSample> edgeSamplesOf(const std::vector<Feature>& features, double spacing_mm);

/** Samples every @p spacing_mm along the lines and the conic arcs (their true shape and extent)
 * of @p wf (model::sampleWireFrame); feature indices as featuresOf(wf): lines, then conics. */
std::vector<EdgeSample> edgeSamplesOf(const model::WireFrame& wf, double spacing_mm);

/** A model's edge samples with the SelfOcclusion::PointSight of each against @p occ (may be
 * null: nothing hidden), computed once per model and spacing and shared by every pose scored. */
struct SightedSamples
{
	SightedSamples(std::vector<EdgeSample> samples, const SelfOcclusion* occlusion);
	std::vector<EdgeSample> samples_O;
	const SelfOcclusion* occ = nullptr;
	std::vector<SelfOcclusion::PointSight> sights;  ///< per sample; empty without occ
	std::vector<SampleBlock> blocks;                ///< samples_O as RunProjection reads them
};

/** Result of one hypothesis in the images. */
struct ImageScore
{
	double score = 0;    ///< supported / considered samples over both images, [0, 1]
	int considered = 0;  ///< samples expected visible and inside an image (both images summed)
	int supported = 0;   ///< of those, within edge_distance_px of an edge of compatible direction
	std::array<double, 2> per_image = {0, 0};  ///< left, right score
	double cost = 0;   ///< mean squared truncated chamfer distance of the considered samples (px²)
	int occluded = 0;  ///< in-view samples hidden by an Occluder (not in considered)
	int outside = 0;   ///< samples not hidden by the object itself but outside the images
};

/** A pose and its ImageScore. */
struct ScoredPose
{
	Eigen::Isometry3d T;
	ImageScore s;
};

/** One image's share of an ImageScore (ImageVerifier::score sums both images'). */
struct ImageCount
{
	int considered = 0;   ///< samples expected visible and inside the image, not occluded
	int supported = 0;    ///< of those, on an edge of compatible direction
	int occluded = 0;     ///< in-view samples hidden by an Occluder
	int outside = 0;      ///< samples not hidden by the object itself but outside the image
	double cost_px2 = 0;  ///< sum of the considered samples' squared truncated distances
};

struct Prospects;
struct RefineMemo;
struct SweptCircle;

/** What lets a count give up early: the score of a pose is wanted only if it can beat a best one
 * (the mean squared distance of the considered samples below max_mean_px2, or more than
 * min_supported samples supported, or a supported fraction above max_fraction; a criterion left
 * at its default never asks for the score). Holds the sums of the samples visited so far (of
 * every image) and the number not visited yet; exceeded() once even the most favourable rest
 * (each unvisited sample considered, supported, at distance 0) can meet none of the criteria, with
 * a relative margin of 1e-12 against rounding. */
struct ScoreCap
{
	double max_mean_px2 = 0;
	int min_supported = INT_MAX;
	double max_fraction = 2;
	double sum_px2 = 0;
	int considered = 0, supported = 0, unvisited = 0;
	bool exceeded() const
	{
		const double reach = considered + unvisited, best_supported = supported + unvisited;
		return sum_px2 >= max_mean_px2 * reach * (1 + 1e-12) && best_supported < min_supported &&
		       best_supported <= max_fraction * reach * (1 - 1e-12);
	}
};

/** The Gauss–Newton terms of the point-to-edge-line residuals of a pose (EdgeImage::addEdgeLines):
 * H = Σ JᵀJ and g = Σ Jᵀ r over the n residuals, J the derivative of a residual (px) by a small
 * motion of the pose: a translation (mm, in L) then a rotation (rad, about L's axes through a
 * point c_L). */
struct EdgeLineTerms
{
	Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
	Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
	double r2 = 0;  ///< Σ r² (px²)
	int n = 0;
};

/** A sample that count() considered and found on an edge of compatible direction (within
 * orientation_tol_deg) near enough to count: within edge_distance_px, or 2 px past the cap
 * truncate_px (the edge-line terms take those within the cap). Its pixel, and its point in the
 * camera's frame (OpenCV axes, mm): what the edge-line terms of the same pose need of it. */
struct AlignedSample
{
	cv::Point2d px;
	Eigen::Vector3d p_C;
};

/** How far the local search of ImageVerifier::refine may take a pose from where it started (the
 * move of the refinement's axis point, and the angle): a refinement refines. Measured without
 * the bound (and before sub-pixel edges): twice the 99th percentile of the moves of the
 * refinements that ended with an image score of 0.6 or more on the rendered sets of seeds 1 and
 * 201 (12.6 mm, 17.3°); a fit to the outline of another object in seed 101 moved 41 mm and 45°
 * to reach the acceptance score. */
constexpr double kRefinementReach_mm = 25, kRefinementReach_deg = 35;
/** @p T_OinL is within kRefinementReach of @p start_OinL: the point @p a_O (model frame) moved
 * no more than kRefinementReach_mm, the rotation between them no more than kRefinementReach_deg. */
bool withinRefinementReach(const Eigen::Isometry3d& T_OinL, const Eigen::Isometry3d& start_OinL,
                           const Eigen::Vector3d& a_O);

/** An object recognised in the same stereo pair, which may hide parts of another: its edge
 * samples (model frame, mm), its solid (SelfOcclusion, for interpenetrates(); may be null) and
 * its pose in L. */
struct Occluder
{
	std::vector<EdgeSample> samples_O;
	const SelfOcclusion* occ = nullptr;
	Eigen::Isometry3d T_OinL = Eigen::Isometry3d::Identity();
};

/** The edge evidence of one image: Canny edges, the distance (px) of every pixel to the nearest
 * edge pixel and that pixel's gradient direction; and the camera (pose in L, K, distortion). */
class EdgeImage
{
 public:
	/** @p grey 8-bit image; @p T_CcvInL pose of the OpenCV camera (x right, y down) in L (mm). */
	EdgeImage(const cv::Mat& grey, const cv::Matx33d& K, const cv::Vec<double, 5>& D,
	          const Eigen::Isometry3d& T_CcvInL, const ImageVerificationOptions& o);

	/** What this image says of the samples of @p s carried by @p T_OinL: of those in front of
	 * the camera, inside the image and not hidden by the object itself (s.occ), how many the
	 * occluders hide, how many are considered and how many of those an edge supports; those not
	 * hidden by the object but outside the image (or more than 45° off the optic axis, or behind
	 * the camera). With @p truncate_px > 0, cost_px2 sums each considered sample's squared
	 * distance to the edges (bilinear, capped at @p truncate_px; the cap when the nearest edge's
	 * direction disagrees). */
	ImageCount count(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	                 double truncate_px = 0) const;
	/** count() with the limbs given (limbsSeen()): the counts, or empty as soon as @p cap (may be
	 * null: never) is exceeded, the samples counted having been added to it. With @p aligned
	 * (may be null), its AlignedSamples in their order (the buffer emptied first). */
	std::optional<ImageCount> count(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	                                const std::vector<EdgeSample>& limbs, double truncate_px,
	                                ScoreCap* cap,
	                                std::vector<AlignedSample>* aligned = nullptr) const;
	/** The samples of @p s (then @p limbs) at @p T_OinL that count() would consider unless the
	 * object hid them, each with whether an edge supports it: what the yaw sweep bounds a
	 * pose's score with before it asks the costly sight tests (Prospects.h). */
	void prospects(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	               const std::vector<EdgeSample>& limbs, Prospects& out) const;
	/** Whether the object (s.occ, seen from this camera as @p view) hides prospect @p k (an
	 * index of Prospects, @p limbs those of the pose): count()'s sight test. */
	bool hides(const SightedSamples& s, const std::vector<EdgeSample>& limbs,
	           const SelfOcclusion::View& view, std::uint32_t k) const;
	/** Whether hides() says no at once, without its costly part (SelfOcclusion::
	 * sharesOutsideFace); false when it cannot tell. */
	bool seenAtOnce(const SightedSamples& s, const SelfOcclusion::View& view,
	                std::uint32_t k) const;
	/** The limbs of the bodies of revolution of s.occ seen from this camera with the object at
	 * @p T_OinL (empty without limbs or s.occ). */
	std::vector<EdgeSample> limbsSeen(const SightedSamples& s,
	                                  const Eigen::Isometry3d& T_OinL) const;
	/** The same into @p limbs (emptied first; its storage is kept). */
	void limbsSeen(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	               std::vector<EdgeSample>& limbs) const;

	/** Adds to @p terms a residual for each sample count() considers that lies on an edge of
	 * compatible direction within @p truncate_px: its signed distance r = n·(px − e) to the line
	 * through its nearest edge pixel e along that pixel's gradient n (as edge-based trackers do;
	 * Drummond & Cipolla 2002), derived through the undistorted pinhole projection. Motions are
	 * about the point @p c_L. */
	void addEdgeLines(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	                  const std::vector<EdgeSample>& limbs, const Eigen::Vector3d& c_L,
	                  double truncate_px, EdgeLineTerms& terms) const;
	/** The same from the AlignedSamples a count() of the pose gave: the same terms. */
	void addEdgeLines(const std::vector<AlignedSample>& aligned, const Eigen::Vector3d& c_L,
	                  double truncate_px, EdgeLineTerms& terms) const;

	/** Marks the image regions of @p occluders: the convex hull of each one's samples projected
	 * without distortion (those outside the image too; the hull of a cylinder's rims is its
	 * silhouette), at the depth of its samples' centroid along this camera's axis; a sample
	 * inside a region and more than @p margin_mm deeper is occluded. Replaces earlier ones. */
	void setOccluders(const std::vector<Occluder>& occluders, double margin_mm);
	/** Depth (mm, this camera) of the occluder at each pixel; +inf where none (empty: none). */
	const cv::Mat& occluderDepth() const { return occluder_z_; }

	/** How one sample fared: its pixel, and whether it was hidden, considered, supported. */
	struct Judged
	{
		cv::Point2d px;
		bool limb = false, hidden = false, supported = false;
	};
	/** Every in-view sample of count() (limbs included), hidden ones too, for drawing. */
	std::vector<Judged> judge(const std::vector<EdgeSample>& s_O, const Eigen::Isometry3d& T_OinL,
	                          const SelfOcclusion* occ) const;

	/** Optical centre in L (mm). */
	Eigen::Vector3d centre_L() const { return T_CcvInL_.translation(); }
	const cv::Mat& edges() const { return edges_; }
	const cv::Mat& distance() const { return dist_; }

 private:
	/** Projects the samples of @p s (then @p limbs) at @p T_OinL; calls @p fn(pixel, tangent
	 * pixel, hidden, limb, point in this camera's frame mm) for those in the image (the hidden
	 * ones only when @p kHiddenToo); @p outside (may be null) counts those not hidden by s.occ
	 * outside it. After each sample, stops when @p stop() says so. */
	template <bool kHiddenToo, class Fn, class Stop>
	void forEachInView(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	                   const std::vector<EdgeSample>& limbs, Fn fn, Stop stop, int* outside) const;
	/** Calls @p fn(run, first, n) for each run of @p samples (those of @p s, from their blocks,
	 * or a pose's limbs) projected at @p T_OinC, while it returns true; false if it stopped. */
	template <class Fn>
	bool forEachRun(const SightedSamples& s, const std::vector<EdgeSample>& samples,
	                const Eigen::Isometry3d& T_OinC, Fn fn) const;
	/** The sight test of sample @p s (@p sight: its PointSight; null for a limb) against
	 * @p occ seen as @p view. */
	bool hiddenBy(const SelfOcclusion& occ, const SelfOcclusion::View& view, const EdgeSample& s,
	              const SelfOcclusion::PointSight* sight) const;
	/** count(), calling @p keep(pixel, point in this camera's frame) for each AlignedSample. */
	template <class Keep>
	std::optional<ImageCount> countKeeping(const SightedSamples& s, const Eigen::Isometry3d& T_OinL,
	                                       const std::vector<EdgeSample>& limbs, double truncate_px,
	                                       ScoreCap* cap, Keep keep) const;
	/** addEdgeLines()'s term of one AlignedSample (none beyond @p truncate_px of the edge). */
	void addEdgeLine(const AlignedSample& a, const Eigen::Vector3d& c_L, double truncate_px,
	                 EdgeLineTerms& terms) const;
	struct Pixel
	{
		int x, y;
	};
	/** The pixel @p px (inside the image) falls on. */
	static Pixel pixelOf(const cv::Point2d& px);
	bool occludedAt(const Pixel& at, double depth_mm) const;
	bool supports(const cv::Point2d& px, const cv::Point2d& tangent_px) const;
	std::uint8_t reachAt(const Pixel& at, double truncate_px) const;  ///< a Reach
	/** The nearest edge at @p at runs within orientation_tol_deg of @p tangent_px. */
	bool oriented(const Pixel& at, const cv::Point2d& tangent_px) const;
	double distanceAt(const cv::Point2d& px) const;  ///< bilinear (px)

	cv::Matx33d K_;
	cv::Vec<double, 5> D_;
	Eigen::Isometry3d T_CcvInL_, T_LinCcv_;
	double dist_px_, sin_tol_;
	bool limbs_, revolution_visibility_;
	double limb_spacing_mm_;
	cv::Mat edges_;  ///< CV_8U, 255 on edges
	cv::Mat dist_;   ///< CV_32F, px to the nearest edge pixel
	cv::Mat reach_;  ///< CV_8U: each pixel's Reach for the cap reach_truncate_px_ (a byte to read)
	double reach_truncate_px_;
	cv::Mat labels_;                    ///< CV_32S, label of the nearest edge pixel
	std::vector<cv::Point2f> normal_;   ///< unit gradient at each label's edge pixel
	std::vector<cv::Point2f> edge_px_;  ///< each label's edge pixel
	/** CV_32FC2: normal_ of each pixel's nearest edge pixel, NaN where it has none (one look-up
	 * for oriented() instead of two that depend on each other). */
	cv::Mat nearest_normal_;
	cv::Mat occluder_z_;  ///< CV_32F, occluders' depth (mm); empty when none
	double occluder_margin_mm_ = 0;
};

/** Both images of a stereo pair: scores hypotheses by their edge support in the left and right
 * images. */
class ImageVerifier
{
 public:
	/** @p left, @p right 8-bit grey (or BGR, converted) images of the size in @p calib. Throws
	 * std::invalid_argument naming what is wrong (empty image, size differing from the
	 * calibration's). */
	ImageVerifier(const cv::Mat& left, const cv::Mat& right, const stereo::StereoCalibration& calib,
	              const ImageVerificationOptions& o);

	/** Oriented chamfer score of the model features @p features_O (model frame, mm) at
	 * @p T_OinL: samples hidden by the object itself (@p occ built on the same features; may be
	 * null) do not count. */
	ImageScore score(const std::vector<Feature>& features_O, const Eigen::Isometry3d& T_OinL,
	                 const SelfOcclusion* occ) const;
	/** The same on samples already taken (edgeSamplesOf with options().sample_spacing_mm). */
	ImageScore score(const std::vector<EdgeSample>& samples_O, const Eigen::Isometry3d& T_OinL,
	                 const SelfOcclusion* occ) const;
	/** The same on samples whose sight is known (what the Recognizer scores with). Without the
	 * cost when not @p with_cost (0): the same counts and score, for less (a quick ranking). */
	ImageScore score(const SightedSamples& samples, const Eigen::Isometry3d& T_OinL,
	                 bool with_cost = true) const;
	/** score() when its cost is below @p max_cost_px2, else empty: gives up as soon as the
	 * samples counted prove that it is not (ScoreCap). What the local search asks of a step. */
	std::optional<ImageScore> scoreIfCheaper(const SightedSamples& samples,
	                                         const Eigen::Isometry3d& T_OinL,
	                                         double max_cost_px2) const;
	/** score(), or empty when the samples counted prove it has neither more than
	 * @p min_supported supported samples nor a score above @p max_score (ScoreCap). What the yaw
	 * sweep asks of a yaw. */
	std::optional<ImageScore> scoreIfMore(const SightedSamples& samples,
	                                      const Eigen::Isometry3d& T_OinL, int min_supported,
	                                      double max_score) const;

	/** Refines @p T_OinL in the images: an options().yaw_step_deg sweep about the model's z axis
	 * through each of @p axes_O, then the local search (edgeLineSearch) from the yaw with the
	 * most supported samples, from the yaw with the highest supported fraction and from
	 * @p T_OinL (those that differ); the refined pose with the most supported samples (then the
	 * lowest cost) is returned if it has no fewer than the swept one, else the swept one. */
	Eigen::Isometry3d refine(const std::vector<EdgeSample>& samples_O,
	                         const Eigen::Isometry3d& T_OinL, const SelfOcclusion* occ,
	                         const std::vector<Eigen::Vector3d>& axes_O) const;
	/** The same on samples whose sight is known. With @p memo (may be null), what the refinements
	 * of the same search have swept and searched is taken from it (RefineMemo), and what this
	 * one does is added. */
	Eigen::Isometry3d refine(const SightedSamples& samples, const Eigen::Isometry3d& T_OinL,
	                         const std::vector<Eigen::Vector3d>& axes_O,
	                         RefineMemo* memo = nullptr) const;
	/** The same from @p start, whose score() is known: the refined pose with its score(). */
	ScoredPose refine(const SightedSamples& samples, const ScoredPose& start,
	                  const std::vector<Eigen::Vector3d>& axes_O, RefineMemo* memo) const;

	/** The edge-line terms of both images at @p T_OinL, motions about @p c_L. */
	EdgeLineTerms edgeLines(const SightedSamples& samples, const Eigen::Isometry3d& T_OinL,
	                        const Eigen::Vector3d& c_L) const;

	/** A copy whose images know the regions hidden by @p occluders (EdgeImage::setOccluders,
	 * options().occluder_margin_mm); scores then leave the occluded samples out. */
	ImageVerifier withOccluders(const std::vector<Occluder>& occluders) const;

	const ImageVerificationOptions& options() const { return opts_; }
	const EdgeImage& image(int i) const { return images_.at(i); }

 private:
	/** Levenberg–Marquardt steps on the edge-line residuals (EdgeImage::addEdgeLines) from
	 * @p start (a pose and its score), rotations about @p axis_O's image; a step is kept only if
	 * it lowers the chamfer cost of score() and stays withinRefinementReach of @p start. */
	ScoredPose edgeLineSearch(const SightedSamples& samples, const ScoredPose& start,
	                          const Eigen::Vector3d& axis_O) const;
	/** refine()'s yaw sweep about the axis through @p a_O: the circle of @p start. */
	SweptCircle sweptAbout(const SightedSamples& samples, const ScoredPose& start,
	                       const Eigen::Vector3d& a_O) const;
	/** sweptAbout() about axis @p k of @p axes_O, or the circle of @p memo it lies on. */
	SweptCircle circleOf(const SightedSamples& samples, const ScoredPose& start,
	                     const std::vector<Eigen::Vector3d>& axes_O, size_t k,
	                     RefineMemo* memo) const;
	/** edgeLineSearch() from @p seed, or the one of @p memo from the same seed and axis. */
	ScoredPose searchedFrom(const SightedSamples& samples, const ScoredPose& seed,
	                        const Eigen::Vector3d& axis_O, RefineMemo* memo) const;
	/** Both images' AlignedSamples of a pose (count()). */
	using AlignedPair = std::array<std::vector<AlignedSample>, 2>;
	/** scoreIfCheaper() keeping the AlignedSamples of the pose in @p aligned. */
	std::optional<ImageScore> scoreIfCheaper(const SightedSamples& samples,
	                                         const Eigen::Isometry3d& T_OinL, double max_cost_px2,
	                                         AlignedPair* aligned) const;
	/** edgeLines() from a pose's AlignedSamples. */
	EdgeLineTerms edgeLines(const AlignedPair& aligned, const Eigen::Vector3d& c_L) const;
	/** The ImageScore of both images' counts (score()'s acceptance rules). */
	ImageScore combined(const std::array<ImageCount, 2>& counts) const;
	/** score(), or empty as soon as @p cap is exceeded. */
	std::optional<ImageScore> scoreUnlessExceeded(const SightedSamples& samples,
	                                              const Eigen::Isometry3d& T_OinL, ScoreCap cap,
	                                              AlignedPair* aligned = nullptr) const;
	ImageVerificationOptions opts_;
	std::vector<EdgeImage> images_;  ///< left, right
};

/** @p grey (the image @p image was built from, 8-bit grey or BGR) darkened, with its Canny edges
 * in white and the samples of EdgeImage::judge drawn: supported green, unsupported red, hidden by
 * the object itself blue; dots for the wire-frame's samples, crosses for limbs. BGR. */
cv::Mat drawJudgement(const cv::Mat& grey, const EdgeImage& image,
                      const std::vector<EdgeSample>& samples_O, const Eigen::Isometry3d& T_OinL,
                      const SelfOcclusion* occ);

}  // namespace mrolr::recog
