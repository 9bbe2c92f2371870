#pragma once
/** The TRC BiSight 4-DOF pan–tilt–vergence stereo head (thesis 4.2.2–4.2.5, eqs 4.9–4.50).
 *
 * Frames (thesis axes everywhere: x left, y up, z forward/along the optic axis):
 *  - C0: head centre, the intersection of the pan and tilt axes, fixed on the base.
 *  - C1: after pan α about the vertical axis,   m_C1 = R_C1fromC0(α) m_C0          (eq 4.14)
 *  - C2: after tilt e about the tilt (x) axis,  m_C2 = R_C2fromC1(e) (m_C1 − p) − c (eq 4.15)
 *  - L, R: after vergence γ about C2's y axis,  m_L  = R_LfromC2(γL) m_C2 − n        (eq 4.16–4.17)
 * with the offsets p_L = (I/2, 0, p), p_R = (−I/2, 0, p) in C1 (eq 4.10), c = (0, c, 0) in C2
 * (eq 4.11) and n = (0, 0, n) in L/R (eqs 4.12–4.13), so the full chain is eq 4.22 / 4.23:
 *   m_L = R_LfromC2(γL) (R_C2fromC1(e) (R_C1fromC0(α) m_G − p_L) − c_L) − n_L.
 * Positive pan turns the head towards +x (left), positive tilt raises the gaze, and positive
 * vergence turns a camera towards +x; symmetric fixation gives γL < 0 < γR = −γL.
 *
 * @code
 *            y (up)
 *            |   z (forward)          L optic centre (x = +I/2)   R optic centre (x = −I/2)
 *            |  /                         o ----------- I ----------- o
 *            | /                           \__ n along the optic axes__/
 *  x (left) _|/ C0 = pan ∩ tilt axes            c up the vergence axes, p forward of C0
 * @endcode
 */

#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/geometry/PinholeCamera.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mrolr::geometry
{
/** The four joint angles of the head in radians (thesis α, e, γL, γR). */
struct HeadAngles
{
	double pan = 0;         ///< α, positive towards +x (left)
	double tilt = 0;        ///< e, positive upwards
	double verg_left = 0;   ///< γL, positive towards +x (left); negative when converging
	double verg_right = 0;  ///< γR, positive towards +x; positive when converging
};

/** Image coordinates of one point in both cameras, pixels (thesis eq 4.24). */
struct StereoPixels
{
	double uL = 0, vL = 0, uR = 0, vR = 0;

	Eigen::Vector4d asVector() const { return {uL, vL, uR, vR}; }
	static StereoPixels fromVector(const Eigen::Vector4d& v) { return {v[0], v[1], v[2], v[3]}; }
};

/** Result of a stereo triangulation: the point and its covariance, both in C0. */
struct Triangulation
{
	Eigen::Vector3d p_GinC0 = Eigen::Vector3d::Zero();  ///< metres, C0 (thesis axes)
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();      ///< m², from the pixel noise σ_px
	/// ∂p_GinC0/∂(uL, vL, uR, vR), m/px; cov = σ_px² · J Jᵀ
	Eigen::Matrix<double, 3, 4> J_wrt_pixels = Eigen::Matrix<double, 3, 4>::Zero();
	double gap_m = 0;  ///< length of the common perpendicular between the two rays
};

/** Which camera of the head. */
enum class Side
{
	Left,
	Right
};

/** Rotation matrices of the head joints (thesis eqs 4.14–4.17), m_to = R · m_from. */
Eigen::Matrix3d R_C1fromC0(double pan);
Eigen::Matrix3d R_C2fromC1(double tilt);
Eigen::Matrix3d R_LfromC2(double vergence);  ///< also R_RfromC2 (same form, eq 4.17)

/** Rotation taking a vector in the computer-vision camera convention (x right, y down, z forward)
 * to the thesis camera convention (x left, y up, z forward): diag(−1, −1, 1), a half-turn about z.
 */
Eigen::Matrix3d R_thesisFromCv();

/** The BiSight head geometry: camera poses, projection, fixation and triangulation. Every method is
 * const and thread-safe. */
class BiSightHead
{
 public:
	explicit BiSightHead(const BiSightOptions& options = BiSightOptions());

	const BiSightOptions& options() const { return options_; }
	/** Intrinsics shared by both cameras (thesis eq 4.7). */
	const PinholeCamera& camera() const { return camera_; }

	/** Pose of the left camera frame L in C0, both in thesis axes (x left, y up, z along the optic
	 * axis): p_C0 = T_LinC0 · p_L. Its translation is the optic centre, eq 4.41. */
	Eigen::Isometry3d T_LinC0(const HeadAngles& angles) const;
	/** Pose of the right camera frame R in C0 (thesis axes), eq 4.42. */
	Eigen::Isometry3d T_RinC0(const HeadAngles& angles) const;
	/** The vertical of C0 (its +y: up when the base stands level) as a unit vector in the left
	 * camera frame L: R_LfromC0 · (0, 1, 0) = T_LinC0(angles).linear()ᵀ · (0, 1, 0). The scene up
	 * direction a recogniser's upright prior needs for a scene reconstructed in L. */
	Eigen::Vector3d up_L(const HeadAngles& angles) const;
	/** Pose of one camera frame in C0 (thesis axes). */
	Eigen::Isometry3d T_CamInC0(Side side, const HeadAngles& angles) const;

	/** Pose in C0 (thesis axes) of the same camera expressed in the usual computer-vision
	 * convention (x right, y down, z forward, as OpenCV and mrpt::img::TCamera use):
	 * T_CamInC0(side) · R_thesisFromCv(). A renderer with an OpenCV-style camera model projects
	 * p_cv = T⁻¹ · p_C0 with the same pixels: fx = focal_px_u, fy = focal_px_v, cx = u0_px,
	 * cy = v0_px (PinholeCamera::toTCamera). */
	Eigen::Isometry3d T_CamCvInC0(Side side, const HeadAngles& angles) const;

	/** The point m_G (C0, metres) in the camera frame, eqs 4.22 / 4.23. */
	Eigen::Vector3d pointInCamera(Side side, const Eigen::Vector3d& p_GinC0,
	                              const HeadAngles& angles) const;

	/** Image coordinates (uL, vL, uR, vR) of m_G (C0, metres), eq 4.24, for any head angles.
	 * If @p J_wrt_point is given it receives the analytic 4×3 Jacobian ∂(uL,vL,uR,vR)/∂m_G.
	 * Throws ProjectionError if the point is not in front of either camera. */
	StereoPixels project(const Eigen::Vector3d& p_GinC0, const HeadAngles& angles,
	                     Eigen::Matrix<double, 4, 3>* J_wrt_point = nullptr) const;

	/** Symmetric fixation (eqs 4.25–4.33): the head angles that bring m_G (C0, metres) onto the
	 * principal point of both cameras, with γR = −γL. Throws FixationError naming the reason for a
	 * point on the pan axis, too close to the head, behind the cameras, or beyond a joint limit. */
	HeadAngles fixate(const Eigen::Vector3d& p_GinC0) const;

	/** The 3D point (C0, metres) seen at @p pixels with the head at @p angles: the midpoint of the
	 * common perpendicular of the two back-projected rays (eqs 4.34–4.50), with its covariance
	 * propagated from independent pixel noise of standard deviation @p sigma_px on each of the four
	 * coordinates. Throws TriangulationError for near-parallel rays or a point behind a camera. */
	Triangulation triangulate(const StereoPixels& pixels, const HeadAngles& angles,
	                          double sigma_px = 1.0) const;

	/** The triangulated point only, without covariance (for Jacobians and benchmarks). */
	Eigen::Vector3d triangulatePoint(const StereoPixels& pixels, const HeadAngles& angles) const;

	/** Throws FixationError unless every angle is within the configured joint limits. */
	void checkJointLimits(const HeadAngles& angles) const;

 private:
	BiSightOptions options_;
	PinholeCamera camera_;
};

}  // namespace mrolr::geometry
