#pragma once
/** A calibrated stereo pair (thesis 4.3.2.1) in OpenCV's conventions: pixel intrinsics K (fx, fy,
 * cx, cy in px), distortion (k1 k2 p1 p2 k3) and the left-to-right rigid transform
 * p_inR = R_RfromL · p_inL + t_LinR_mm, both cameras with OpenCV's axes (x right, y down, z along
 * the optic axis). The thesis left-camera frame (x left, y up, z forward) is this frame rotated
 * 180° about z; StereoScene converts. Stored as an `.ini` section (see docs/model.md). */

#include <mrpt/config/CConfigFileBase.h>

#include <opencv2/core.hpp>

#include <iosfwd>
#include <string>

namespace mrolr::stereo
{
/** Intrinsics, distortion and extrinsics of a stereo pair, plus the quality of the fit. */
struct StereoCalibration
{
	cv::Size image_size;                                                    ///< px
	cv::Matx33d K_left = cv::Matx33d::eye(), K_right = cv::Matx33d::eye();  ///< px
	cv::Vec<double, 5> D_left = {}, D_right = {};                           ///< k1 k2 p1 p2 k3
	cv::Matx33d R_RfromL = cv::Matx33d::eye();
	cv::Vec3d t_LinR_mm = {};  ///< position of the left centre seen from the right camera, mm
	double rms_px = 0;         ///< stereoCalibrate's RMS reprojection error, px
	int pairs_used = 0;

	/** Distance between the optical centres, mm. */
	double baseline_mm() const { return cv::norm(t_LinR_mm); }

	/** Reads section @p section (keys listed in docs/model.md); errors name file, section, key. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

	/** Writes the same keys that loadFromConfigFile reads, 17 significant digits. */
	void saveToConfigFile(mrpt::config::CConfigFileBase& cfg, const std::string& section) const;

	/** Human-readable summary. */
	void dump(std::ostream& out) const;
};

/** Loads the calibration from section [stereo_calib] of an .ini file. */
StereoCalibration loadStereoCalibration(const std::string& ini_path);

/** Writes the calibration as section [stereo_calib] of a new .ini file. */
void saveStereoCalibration(const StereoCalibration& calib, const std::string& ini_path);

}  // namespace mrolr::stereo
