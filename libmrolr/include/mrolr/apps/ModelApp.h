#pragma once
/** `mrolr-model`: wire-frame models from stereo (thesis 4.3, 6.1, 6.2, 7.1).
 *
 *     mrolr-model build --turntable DIR --out M.wf [--truth T.wf] [--json]
 *                       [--align turntable|recog]
 *     mrolr-model scene --left L.png --right R.png (--calib C.ini | --head pan,tilt,vl,vr) --out
 * S.wf mrolr-model edit M.wf [--out M2.wf] [--remove 3,5] [--remove-box x0,y0,z0,x1,y1,z1]
 *                 [--add-line x1,y1,z1,x2,y2,z2] [--add-conic cx,cy,cz,nx,ny,nz,ax,ay,az,a,b,t1,t2]
 *                 [--merge] [--grasp x,y,z,yaw,pitch,roll] [--list]
 *     mrolr-model cliques M.wf [--out M2.wf] [--replace] [--json]
 *     mrolr-model show M.wf --png P.png [--scene3d S.3Dscene] [--azimuth A] [--elevation E]
 *     mrolr-model stats M.wf [--truth T.wf [--depth D.png [--depth-right DR.png]
 *                            (--calib C.ini | --head ANGLES)]] [--json]
 *
 * Options of every stage come from --config (default config/model.ini). Head angles in degrees. */

#include <mrolr/model/ModelStats.h>
#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
class ModelApp
{
 public:
	/** Parses the subcommand and its arguments; throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);

	/** Runs the subcommand, printing text or JSON to @p out; returns the exit code. */
	int run(std::ostream& out);

	// Inputs (set by initialize)
	std::string command;  ///< build, scene, edit, cliques, show, stats
	std::string model_path, out_path, truth_path, config_path = "config/model.ini";
	std::string turntable_dir, left_png, right_png, calib_path, bisight_path = "config/bisight.ini";
	std::string png_path, scene3d_path;
	std::string depth_png;  ///< stats: left depth image (mm) restricting the truth to what is seen
	std::string depth_right_png;  ///< stats: right depth image: the truth both cameras see
	std::optional<std::vector<double>> head_deg;  ///< pan, tilt, γL, γR
	std::vector<int> remove_ids;
	std::vector<std::vector<double>> remove_boxes, add_lines, add_conics;
	std::optional<std::vector<double>> grasp;
	std::optional<double> azimuth_deg, elevation_deg;
	/** build: "turntable" (the known angles) or "recog" (views registered by recognition,
	 * thesis 6.5, RecognitionAlignment.h). */
	std::string align = "turntable";
	bool merge = false, list = false, replace = false, json = false, help_shown = false;
	/** stats --per-feature: the recovered length of every (visible) true feature in the report
	 * (`truth_features`), for a breakdown of what a scene model misses. */
	bool per_feature = false;

	// Results (set by run)
	model::WireFrame result;
	std::optional<model::ModelQuality> quality;
	nlohmann::json report;

 private:
	void parseBuild(const std::vector<std::string>& a);
	void parseScene(const std::vector<std::string>& a);
	void parseEdit(const std::vector<std::string>& a);
	void parseCliques(const std::vector<std::string>& a);
	void parseShow(const std::vector<std::string>& a);
	void parseStats(const std::vector<std::string>& a);
	int runBuild();
	/** build --align recog: the model of @p set, registrations in report["registration"]. */
	model::WireFrame buildByRecognition(const model::TurntableSet& set,
	                                    const stereo::SceneOptions& so,
	                                    const model::TurntableOptions& to,
	                                    const std::string& truth_path);
	int runScene();
	int runEdit(std::ostream& out);
	int runCliques();
	int runShow();
	int runStats();
	void addStatsToReport(const model::WireFrame& truth);
	void addStatsToReport(const model::WireFrame& m, const model::WireFrame& truth);
	stereo::StereoCalibration viewCalibration() const;  ///< --calib, else the head at --head
	/** Statistics of result against --truth (visible part with --depth). */
	void statsAgainstTruth(const std::string& name);
	/** stats --per-feature: recovery of each true feature of @p truth by @p m (same frame). */
	nlohmann::json perFeatureJson(const model::WireFrame& m, const model::WireFrame& truth) const;
	/** @p m in the truth's frame (a C0 model with --head goes back to the left camera); throws
	 * std::runtime_error naming both files when the frames differ otherwise. */
	model::WireFrame inFrameOf(const model::WireFrame& m, const model::WireFrame& truth,
	                           const std::string& name) const;
};

}  // namespace mrolr::apps
