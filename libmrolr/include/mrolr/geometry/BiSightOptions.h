#pragma once
/** Parameters of the BiSight head (thesis 4.2.2, eqs 4.9–4.13) and of its cameras (4.2.1), read
 * from config/bisight.ini section [bisight]. Every key carries its unit; a missing or malformed key
 * is a mrolr::util::ConfigError naming file, section and key. */

#include <mrolr/geometry/PinholeCamera.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::geometry
{
/** Head offsets, intrinsics and joint limits. The defaults equal config/bisight.ini; the thesis
 * gives I = 0.25 m and f·k_v = 807 px (5.3.1); the other values are assumptions documented there.
 */
struct BiSightOptions
{
	double interocular_m = 0.25;   ///< I, distance between the vergence axes (thesis 5.3.1)
	double head_height_m = 1.0;    ///< M_h, head centre C0 above the base centre (eq 4.9)
	double pan_offset_m = 0.03;    ///< p, C0 to each vergence axis along C1's z (eq 4.10)
	double tilt_offset_m = 0.05;   ///< c, tilt axis to optic axis along the vergence axis (4.11)
	double optic_offset_m = 0.06;  ///< n, vergence axis to optic centre along the optic axis (4.12)
	double focal_px_u = 807;       ///< f·k_u, pixels
	double focal_px_v = 807;       ///< f·k_v, pixels (thesis 5.3.1)
	double u0_px = 320;            ///< principal point column
	double v0_px = 240;            ///< principal point row
	int image_width_px = 640;
	int image_height_px = 480;
	double pan_limit_deg = 90;       ///< |α| allowed, degrees
	double tilt_limit_deg = 45;      ///< |e| allowed, degrees
	double vergence_limit_deg = 40;  ///< |γL|, |γR| allowed, degrees

	/** Reads every key above from @p section; all keys are required. Throws util::ConfigError
	 * naming file, section and key for a missing, malformed or out-of-range value. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

	/** Loads section [bisight] of the .ini file @p path (ConfigError if the file is missing). */
	static BiSightOptions fromFile(const std::string& path, const std::string& section = "bisight");

	/** Writes the keys as `key = value` lines, readable back by loadFromConfigFile. */
	void dump(std::ostream& out) const;

	/** The intrinsics shared by both cameras. */
	PinholeCamera camera() const;
};

}  // namespace mrolr::geometry
