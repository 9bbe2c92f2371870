#pragma once
/** The pinhole camera of thesis 4.2.1 (eqs 4.1–4.8) in the thesis camera axes: x left, y up,
 * z along the optic axis, pixels with (0, 0) at the top-left corner, u to the right, v down:
 *   u = u0 − f·k_u · x/z,   v = v0 − f·k_v · y/z                                     (eq 4.2)
 * Because the thesis x and y axes point opposite to the computer-vision ones (x right, y down),
 * the same pixels come from the usual K = [fx 0 cx; 0 fy cy; 0 0 1] with fx = f·k_u, fy = f·k_v,
 * cx = u0, cy = v0 applied to p_cv = diag(−1, −1, 1) · p_thesis; toTCamera/fromTCamera convert. */

#include <mrolr/geometry/GeometryError.h>

#include <mrpt/img/TCamera.h>

#include <Eigen/Core>

namespace mrolr::geometry
{
/** Intrinsics and projection of one distortion-free pinhole camera (thesis eqs 4.1–4.8). */
struct PinholeCamera
{
	double focal_px_u = 807;  ///< f·k_u, pixels (thesis 5.3.1 gives f·k_v = 807; square pixels)
	double focal_px_v = 807;  ///< f·k_v, pixels (thesis 5.3.1)
	double u0_px = 320;       ///< principal point column (image centre in the ideal case, 4.2.1)
	double v0_px = 240;       ///< principal point row
	int width_px = 640;
	int height_px = 480;

	/** Pixel (u, v) of the point m (camera frame, thesis axes, any length unit), eq 4.2. If
	 * @p J is given it receives ∂(u,v)/∂m. Throws ProjectionError unless m_z > 0. */
	Eigen::Vector2d project(const Eigen::Vector3d& m,
	                        Eigen::Matrix<double, 2, 3>* J = nullptr) const;

	/** The ray of pixel (u, v): the direction C⁻¹ (u, v, 1)ᵀ scaled to z = 1 (eq 4.6), camera
	 * frame, thesis axes. project(backProject(uv)) = uv. */
	Eigen::Vector3d backProject(const Eigen::Vector2d& uv) const;

	/** ∂backProject/∂(u, v), 3×2 (constant). */
	Eigen::Matrix<double, 3, 2> backProjectJacobian() const;

	/** The calibration matrix C of eq 4.7: (u, v, 1)ᵀ ∝ C · m. */
	Eigen::Matrix3d calibrationMatrix() const;
	/** C⁻¹ in closed form, eq 4.8. */
	Eigen::Matrix3d inverseCalibrationMatrix() const;

	/** True when the pixel lies inside the image [0, width) × [0, height). */
	bool isInImage(const Eigen::Vector2d& uv) const;

	/** The same camera as an MRPT camera (x right, y down): fx = f·k_u, fy = f·k_v, cx = u0,
	 * cy = v0, no distortion. */
	mrpt::img::TCamera toTCamera() const;
	/** The inverse of toTCamera; throws GeometryError if @p cam has lens distortion, which this
	 * model does not represent. */
	static PinholeCamera fromTCamera(const mrpt::img::TCamera& cam);
};

}  // namespace mrolr::geometry
