#pragma once
/** Where to search an image for a feature (thesis 5.2.1, 5.3, 5.5.4).
 *
 * Ellipse (eqs 5.37–5.39): the image position u = (u, v) of a feature is a function of its
 * predicted measurement; to first order its covariance is U = J S Jᵀ with J the 2×3 Jacobian of
 * the projection into one camera. The search region is {u : (u − û)ᵀ U⁻¹ (u − û) ≤ n²} for n
 * standard deviations (3 by default).
 *
 * Epipolar band (5.3): a left-image pixel back-projects to a ray; its image in the right camera is
 * a line segment (depths between a minimum and a maximum) and the match is sought within ± a band
 * (7 px) of it. */

#include <mrolr/geometry/BiSightHead.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace mrolr::vision
{
/** An n-σ ellipse in one image, pixels. */
struct ImageEllipse
{
	Eigen::Vector2d centre = Eigen::Vector2d::Zero();   ///< predicted pixel (u, v)
	Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();  ///< U, px²
	double n_sigma = 3;

	/** Squared Mahalanobis distance of @p uv from the centre, in σ². */
	double mahalanobis2(const Eigen::Vector2d& uv) const;
	/** True when @p uv lies inside the n-σ ellipse. */
	bool contains(const Eigen::Vector2d& uv) const { return mahalanobis2(uv) <= n_sigma * n_sigma; }
	/** The smallest integer rectangle that holds the ellipse (half-widths n·√U_uu, n·√U_vv). */
	cv::Rect boundingBox() const;
	/** Area of the ellipse in px² (π n² √det U). */
	double area() const;
};

/** The ellipse of a point p_GinC0 (C0, metres) with covariance @p cov_C0 (m²) in camera @p side
 * with the head at @p angles (eqs 5.37–5.39): U = J cov Jᵀ, J = ∂u/∂p_GinC0 from the head model.
 * Throws geometry::ProjectionError when the point is behind the camera. */
ImageEllipse projectPointCovariance(const geometry::BiSightHead& head, geometry::Side side,
                                    const geometry::HeadAngles& angles,
                                    const Eigen::Vector3d& p_GinC0, const Eigen::Matrix3d& cov_C0,
                                    double n_sigma);

/** The same from a predicted ideal-head measurement h = (pan, elevation, vergence) (eq 5.40) and
 * its innovation covariance S (rad², eq 5.36): the point is idealHeadInverse(h) and its covariance
 * G S Gᵀ with G = ∂p/∂h, so U = (J G) S (J G)ᵀ. */
ImageEllipse projectInnovation(const geometry::BiSightHead& head, geometry::Side side,
                               const geometry::HeadAngles& angles, const Eigen::Vector3d& h_pred,
                               const Eigen::Matrix3d& S, double n_sigma);

/** A segment of an image line, pixels, and a band of half-width band_px around it. */
struct EpipolarBand
{
	Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  ///< end points
	double band_px = 7;

	/** Distance of @p uv from the segment, pixels. */
	double distance(const Eigen::Vector2d& uv) const;
	bool contains(const Eigen::Vector2d& uv) const { return distance(uv) <= band_px; }
	/** The smallest integer rectangle that holds the band. */
	cv::Rect boundingBox() const;
};

/** The band in the right image for the left-image pixel @p uvL with the head at @p angles: the
 * projections of the points of the left ray at depths min_depth_m … max_depth_m (clipped to the
 * part in front of the right camera). Throws geometry::ProjectionError if no part of the ray is in
 * front of the right camera. */
EpipolarBand epipolarBand(const geometry::BiSightHead& head, const geometry::HeadAngles& angles,
                          const Eigen::Vector2d& uvL, double min_depth_m, double max_depth_m,
                          double band_px);

}  // namespace mrolr::vision
