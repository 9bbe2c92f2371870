#pragma once
/** `mrolr-head`: the BiSight head geometry from the command line, for calibrating and debugging the
 * head (thesis 4.2.3–4.2.5 and eq 5.40). Points in metres in C0 (x left, y up, z forward),
 * angles in radians, pixels as doubles:
 *
 *     mrolr-head [--config FILE] [--json] [--sigma-px S] COMMAND ARGS...
 *       fixate X Y Z                                  -> pan tilt verg_left verg_right
 *       project X Y Z PAN TILT VL VR                  -> uL vL uR vR
 *       triangulate UL VL UR VR PAN TILT VL VR        -> X Y Z   (+ cov, 3x3 m², in JSON)
 *       measure X Y Z                                 -> pan elevation vergence (ideal head)
 */

#include <mrolr/geometry/BiSightHead.h>

#include <Eigen/Core>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
class HeadApp
{
 public:
	/** Parses the command line (argv[0] first, negative numbers protected by
	 * util::argsWithNegativeNumbersProtected); throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);

	/** Loads the configuration, runs the command and prints its outputs (one line of numbers, or
	 * one JSON object keyed by the output names) to @p out. Returns the exit code. Geometric
	 * failures (an unfixatable point, parallel rays) throw geometry::GeometryError. */
	int run(std::ostream& out);

	// Inputs (set by initialize)
	std::string config_path;      ///< --config; empty means config/bisight.ini
	std::string command;          ///< fixate | project | triangulate | measure
	std::vector<double> numbers;  ///< the command's positional numbers
	double sigma_px = 1.0;        ///< pixel noise for triangulate's covariance
	bool json = false;
	bool help_shown = false;  ///< --help was printed; run() does nothing

	// Results (set by run)
	geometry::BiSightOptions options;  ///< as loaded from the configuration
	std::vector<std::string> output_names;
	std::vector<double> output_values;
	std::optional<Eigen::Matrix3d> cov;  ///< triangulate only

	/** The configuration used when --config is not given: config/bisight.ini in the working
	 * directory if it exists, else the one in the source tree. */
	static std::string defaultConfigPath();

 private:
	void print(std::ostream& out) const;
};

}  // namespace mrolr::apps
