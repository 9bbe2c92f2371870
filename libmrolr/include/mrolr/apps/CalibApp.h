#pragma once
/** `mrolr-calib`: stereo calibration from checkerboard image pairs (thesis 4.3.2.1).
 *
 *     mrolr-calib --left 'DIR/?_left.jpg' --right 'DIR/?_right.jpg' --board 9x6 --square-mm 34 \
 *                 --out config/calib_mrpt_bumblebee.ini [--json]
 */

#include <mrolr/stereo/StereoCalibration.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class CalibApp
{
 public:
	/** Parses the command line; throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);

	/** Calibrates, writes the .ini, prints a summary (or JSON) to @p out. Returns the exit code. */
	int run(std::ostream& out);

	// Inputs (set by initialize)
	std::vector<std::string> left_files, right_files;
	std::string board_text = "9x6", out_path;
	double square_mm = 0;
	bool json = false;
	bool help_shown = false;  ///< --help was printed; run() does nothing

	// Result (set by run)
	stereo::StereoCalibration result;
};

}  // namespace mrolr::apps
