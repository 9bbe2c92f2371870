#pragma once
/** `mrolr-sim`: the simulated lab from the command line (docs/sim.md):
 *
 *     mrolr-sim --world FILE --out RUN.rawlog                 drive the waypoints and record
 *     mrolr-sim --world FILE --snapshot --pose z,x,phi_deg --head pan,tilt,vl,vr --out DIR
 *     mrolr-sim --world FILE --scene3d OUT.3Dscene            the world for SceneViewer3D
 *     mrolr-sim --world FILE --turntable OBJECT --out DIR     turntable sequence + calibration
 *     mrolr-sim --make-textures DIR                           write the procedural textures
 *
 * Head angles on the command line are in degrees (thesis α, e, γL, γR). */

#include <mrolr/geometry/BiSightHead.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class SimApp
{
 public:
	/** Parses the command line (argv[0] first); throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);
	/** Runs the selected command, printing progress and a summary to @p out. */
	int run(std::ostream& out);

	// Inputs
	std::string world_path, out_path, scene3d_path, turntable_object, textures_dir;
	std::string bisight_path;     ///< head configuration (default config/bisight.ini)
	std::string sim_config_path;  ///< simulation configuration (default config/sim.ini)
	bool snapshot = false, json = false, help_shown = false;
	std::vector<double> pose_zxphi_deg{0, 0, 0};  ///< --pose z, x (m), φ (deg)
	std::vector<double> head_deg{0, 0, 0, 0};     ///< --head pan, tilt, γL, γR (deg)
	int max_steps = 0;  ///< --max-steps: stop a recording run early (0 = whole route)

	// Results
	int frames_written = 0;
	double render_s = 0;                ///< total time spent rendering
	double total_s = 0;                 ///< total wall-clock time of run()
	double odometry_final_error_m = 0;  ///< recording: |odometry − truth| (position, m) at the end
	std::vector<std::string> files_written;

	/** A path in the working directory if it exists, else in the source tree. */
	static std::string projectFile(const std::string& relative);

 private:
	int runSnapshot(std::ostream& out);
	int runScene3d(std::ostream& out);
	int runRecording(std::ostream& out);
	int runTurntable(std::ostream& out);
	int runMakeTextures(std::ostream& out);
	void printSummary(std::ostream& out) const;
};

}  // namespace mrolr::apps
