#pragma once
/** Geometry, motor scale factors and joint limits of the UMI RTX arm (thesis appendix B.3), read
 * from config/arm_rtx.ini section [rtx]. Lengths in mm, angles in degrees, limits in motor encoder
 * counts. The defaults equal config/arm_rtx.ini. */

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::arm
{
/** The six motors of the RTX, in the order of RtxOptions::limits and MotorCounts. */
enum class Motor
{
	Column = 0,  ///< the vertical column (zed), drives d1
	Shoulder,    ///< q2
	Elbow,       ///< q3
	Yaw,         ///< q4, wrist yaw about the vertical
	Wrist1,      ///< differential wrist motor 1: (pitch, roll) = (90° − q5, q6)
	Wrist2,      ///< differential wrist motor 2
};
constexpr int kMotorCount = 6;

/** "column", "shoulder", ... as used in config keys and messages. */
const char* motorName(Motor m);

/** Inclusive range of encoder counts. */
struct CountRange
{
	double min = 0;
	double max = 0;
};

/** Parameters of the RTX. Denavit–Hartenberg values from the A-matrices of B.3.1; scale factors and
 * the shoulder, elbow and column limits and the wrist radius from compute_xyz (B.3.3.1). The yaw
 * and wrist-motor limits are not in the thesis: their defaults (±110°, ±180°) are assumptions. */
struct RtxOptions
{
	double a2_mm = 254;       ///< upper arm length (A2)
	double a3_mm = 254;       ///< forearm length (A3)
	double d6_mm = 177;       ///< wrist centre to gripper grasp point along the approach axis (A6)
	double q1_fixed_deg = 0;  ///< q1, rotation of the column; fixed on the real arm
	double d1_top_mm = 922;   ///< d1 at column count 0 (the thesis's initial d1, column at the top)

	double column_mm_per_count = 0.2667;
	double shoulder_deg_per_count = 0.03422;
	double elbow_deg_per_count = 0.06844;
	double yaw_deg_per_count = 0.10267;
	double wrist_deg_per_count = 0.07415;

	/** Limits per motor in counts, indexed by Motor. */
	CountRange limits[kMotorCount] = {{-3554, 0},    {-2630, 2630}, {-2630, 2206},
	                                  {-1071, 1071}, {-2428, 2428}, {-2428, 2428}};
	double wrist_radius_max_mm = 507;  ///< horizontal distance column axis → wrist centre

	/** Reads every key (see config/arm_rtx.ini); throws util::ConfigError naming file, section and
	 * key for a missing, malformed or out-of-range value. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	/** Loads @p section of the .ini file @p path (ConfigError if the file cannot be opened). */
	static RtxOptions fromFile(const std::string& path, const std::string& section = "rtx");
	/** Writes `key = value` lines readable by loadFromConfigFile. */
	void dump(std::ostream& out) const;

	const CountRange& limit(Motor m) const { return limits[static_cast<int>(m)]; }
};

}  // namespace mrolr::arm
