#pragma once
/** Object models from turntable stereo views (thesis 6.1, B.2.1): each view is reconstructed
 * (stereo::reconstructScene), moved into the object frame O with the calibrated camera-to-turntable
 * transform and the known turntable angle, cut to the object's cylinder above the table, and all
 * views are integrated (integrateViews): circles fitted to the arcs of all views together
 * (TurntableBuilderRims.h), single-view features kept when other views see them, contours of round
 * bodies dropped (TurntableBuilderSupport.h), then duplicated segments merged (mergeDuplicates).
 *
 * A turntable directory holds `turntable.ini` (docs/model.md "Turntable directories"):
 *
 *     [turntable]
 *     object = can
 *     calib = calib.ini                  # stereo calibration, relative to the directory
 *     R_TfromL = r11 r12 r13 r21 ... r33  # left camera L (thesis axes) to turntable frame T
 *     t_LinT_mm = x y z                  # p_T = R_TfromL · p_L + t_LinT_mm
 *     views = 8
 *     truth = can.wf                     # optional exact model for statistics
 *     [view_0]
 *     left = view_0_left.png
 *     right = view_0_right.png
 *     angle_deg = 0                      # object turned by this about T's z: p_T = Rz · p_O
 */

#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/TurntableBuilderRims.h>
#include <mrolr/model/TurntableBuilderSupport.h>
#include <mrolr/model/TurntableRimChords.h>
#include <mrolr/model/TurntableRimImages.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace mrolr::model
{
/** One stereo view of the turntable. */
struct TurntableView
{
	std::string left_png, right_png;  ///< absolute or relative to the working directory
	double angle_deg = 0;
};

/** The contents of a turntable directory. */
struct TurntableSet
{
	std::string object;
	std::string calib_path, truth_path;  ///< truth_path empty when not given
	Eigen::Isometry3d T_LinT_mm = Eigen::Isometry3d::Identity();
	std::vector<TurntableView> views;
};

/** Reads DIR/turntable.ini; errors name the file, section and key. */
TurntableSet loadTurntableSet(const std::string& dir);

/** Integration options ([turntable] section of config/model.ini). */
struct TurntableOptions
{
	double keep_radius_mm = 150;  ///< features farther from T's z axis are background
	double min_height_mm =
	    -4;  ///< features lower than this are below the table (z = 0 is the table top)
	double max_height_mm = 400;
	int min_views = 2;  ///< a feature must be seen in this many views (dropUnsupported, support)
	MergeOptions merge;
	ViewSupportOptions support;  ///< which single-view features are edges (buildFromTurntable)
	RimOptions rims;             ///< circles fitted to the arcs of all views (buildFromTurntable)
	RimImageOptions rim_images;  ///< horizontal rims' arcs completed from the views' images
	RimChordOptions rim_chords;  ///< horizontal rims from straight chords across views

	/** The shipped integration: the steps' defaults with the values docs/model.md measured on the
	 * lab objects (reasons in TurntableBuilder.cpp); [turntable] of a file sets the crop and
	 * min_views, every other key is optional and overrides one of these. */
	TurntableOptions();
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/** Keeps the features that lie entirely within the object's cylinder (frame O). */
void cropToObject(WireFrame& wf, const TurntableOptions& options);

/** One reconstructed view in frame O (cropped, not merged). */
WireFrame viewInObjectFrame(const stereo::StereoScene& scene, const Eigen::Isometry3d& T_LinT_mm,
                            double angle_deg, const TurntableOptions& options);

/** The scene options of a turntable view: @p scene_options without corner-placed lines
 * (segment_corner_lines), which on a rim seen nearly edge-on join its short chords into straight
 * 3D lines and so take away the chords the rim is recovered from (rimsFromChords; the bottle's
 * neck rim). */
stereo::SceneOptions turntableSceneOptions(const stereo::SceneOptions& scene_options);

/** Builds the object model from all views (with turntableSceneOptions), merged; ids renumbered
 * 1, 2, … */
WireFrame buildFromTurntable(const TurntableSet& set, const stereo::SceneOptions& scene_options,
                             const TurntableOptions& options);

/** The integration of buildFromTurntable: @p views in frame O at turntable angles @p angles_deg
 * (their left images' @p edges, may be empty) keep the features other views support
 * (keepFeaturesSeenFromNearViews), are joined and merged (mergeDuplicates); ids renumbered. */
WireFrame integrateViews(std::vector<WireFrame> views, const std::vector<double>& angles_deg,
                         const std::vector<ViewEdges>& edges, const TurntableOptions& o);

/** Drops features of @p merged that fewer than @p min_views of the single views duplicate. */
size_t dropUnsupported(WireFrame& merged, const std::vector<WireFrame>& views, int min_views,
                       const MergeOptions& o);

/** Renumbers ids 1, 2, … (lines first) and drops cliques (they named old ids). */
void renumber(WireFrame& wf);

}  // namespace mrolr::model
