#pragma once
/** 3D straight-line and conic segments fitted to stereo-matched edge strings (TINA's Geom3, thesis
 * 4.3.2.3). The image position of an edgel is precise while its depth is noisy, so each fit uses
 * the rectified left image geometry and the fact that disparity is an affine function of image
 * position on a plane (and of arc length along a straight line): a line is a 2D line plus a linear
 * disparity profile, a conic is a 2D ellipse plus a disparity plane, both back-projected exactly.
 * Coordinates are millimetres in the thesis left camera frame L (x left, y up, z along the optic
 * axis). */

#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::stereo
{
/** A matched edgel: rectified left pixel and disparity (px), and its 3D point (mm, L). */
struct StereoEdgel
{
	cv::Point2d xy_px;
	double d_px = 0;
	Eigen::Vector3d p_L_mm = Eigen::Vector3d::Zero();
};

/** A fitted 3D segment, endpoints in mm (L); rms_mm: RMS distance of its edgels from the line. */
struct LineFit3
{
	Eigen::Vector3d p1 = Eigen::Vector3d::Zero(), p2 = Eigen::Vector3d::Zero();
	double rms_mm = 0;
	int edgels = 0;
};

/** A fitted 3D conic arc with model::Conic3's parametrisation (centre, unit normal, unit major
 * axis, semi-axes a >= b, arc t1 < t2 of x(t) = c + a cos t · major + b sin t · (normal × major)).
 * rms_mm: RMS distance of the inlier edgels (within 3 median distances) from the arc. */
struct ConicFit3
{
	Eigen::Vector3d centre = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ(),
	                major = Eigen::Vector3d::UnitX();
	double a = 0, b = 0, t1 = 0, t2 = 0;
	double rms_mm = 0;
	int edgels = 0;
	Eigen::Vector3d pointAt(double t) const;
};

/** Options of string segmentation and fitting. */
struct FitOptions
{
	double line_tol_px = 1.0;          ///< max 2D distance of edgels from a line
	double conic_tol_px = 1.0;         ///< max 2D distance of edgels from an ellipse
	double min_arc_deg = 60;           ///< a conic must span at least this angle
	double max_conic_radius_px = 400;  ///< larger ellipses are treated as lines
	int min_line_edgels = 10;
	int min_conic_edgels = 16;
	double max_rms_mm = 4;  ///< 3D fits worse than this are dropped
	int max_gap_edgels =
	    40;  ///< unmatched edgels bridged inside a 3D string (edge parts along the scanlines)
	double max_disparity_jump_px = 1.5;  ///< between consecutive edgels of a 3D string

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Straight line through the edgels, or nothing if too few or too poor (tolerances in options). */
std::optional<LineFit3> fitLine3(const std::vector<StereoEdgel>& e, const Rectifier& rect,
                                 const FitOptions& o);

/** Conic through the edgels (in string order), or nothing if too few, too short an arc or poor. */
std::optional<ConicFit3> fitConic3(const std::vector<StereoEdgel>& e, const Rectifier& rect,
                                   const FitOptions& o);

/** The 2D ellipse through image points given in order (px), or nothing unless the points lie
 * within conic_tol_px of it, span at least min_arc_deg and its semi-axes lie in
 * (2, max_conic_radius_px]. */
std::optional<cv::RotatedRect> fitEllipse2D(const std::vector<cv::Point2d>& pts,
                                            const FitOptions& o);

/** A 3D conic from its 2D image ellipse @p el (rectified left image), the disparity plane of the
 * matched edgels @p matched (at least 3, spread over the arc), and the arc covered by the ordered
 * image points @p arc_px; nothing if the fit is worse than max_rms_mm. */
std::optional<ConicFit3> conicFromEllipse(const cv::RotatedRect& el,
                                          const std::vector<cv::Point2d>& arc_px,
                                          const std::vector<StereoEdgel>& matched,
                                          const Rectifier& rect, const FitOptions& o);

/** Line and conic segments of one 3D edge string: top-down splitting in the image (a piece that is
 * straight within line_tol_px is a line, one that is elliptical within conic_tol_px over
 * min_arc_deg is a conic, anything else splits at the farthest edgel from its chord). */
void segmentString(const std::vector<StereoEdgel>& e, const Rectifier& rect, const FitOptions& o,
                   std::vector<LineFit3>& lines, std::vector<ConicFit3>& conics);

}  // namespace mrolr::stereo
