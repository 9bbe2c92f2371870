#pragma once
/** Wire-frame models of lines and conics (thesis 6.1–6.3): the common type of object models and
 * scene models. Coordinates are millimetres in the frame named by WireFrame::frame. The text format
 * `.wf` (WireFrameIO.h) stores exactly these fields. */

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

#include <string>
#include <vector>

namespace mrolr::model
{
/** The frame a wire-frame's coordinates are expressed in. */
enum class WireFrameFrame
{
	Object,  ///< O, the object model frame (thesis 6.1)
	LeftCamera,  ///< L, the left camera (z along the optic axis, x left, y up)
	C0,  ///< the head centre frame
};

/** A 3D straight-line segment, endpoints in mm. */
struct Line3
{
	int id = 0;
	Eigen::Vector3d p1 = Eigen::Vector3d::Zero();
	Eigen::Vector3d p2 = Eigen::Vector3d::Zero();
	double length() const { return (p2 - p1).norm(); }
	Eigen::Vector3d direction() const { return (p2 - p1).normalized(); }
};

/** A 3D conic arc (circle when a == b): centre, unit plane normal, unit major-axis direction (in the
 * plane), semi-axes a >= b in mm, and the arc from parameter t1 to t2 (rad) of
 * x(t) = centre + a cos t · major + b sin t · (normal × major). */
struct Conic3
{
	int id = 0;
	Eigen::Vector3d centre = Eigen::Vector3d::Zero();
	Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
	Eigen::Vector3d major = Eigen::Vector3d::UnitX();
	double a = 0;
	double b = 0;
	double t1 = 0;
	double t2 = 0;
	/** Point on the conic at parameter t (mm). */
	Eigen::Vector3d pointAt(double t) const
	{
		return centre + a * std::cos(t) * major + b * std::sin(t) * normal.cross(major);
	}
};

/** Grasp point of an object model (thesis 6.1(b)): position in mm and yaw, pitch, roll in degrees. */
struct Grasp
{
	Eigen::Vector3d p_mm = Eigen::Vector3d::Zero();
	double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;
};

/** A clique (thesis fig 7.1.12): a focus feature and the ids of its members (focus included or
 * not, as written). */
struct Clique
{
	int focus = 0;
	std::vector<int> members;
};

/** A wire-frame model: lines, conics, an optional grasp and optional hand-chosen cliques. */
struct WireFrame
{
	std::string name;  ///< file stem or object name; not stored in the file
	WireFrameFrame frame = WireFrameFrame::Object;
	std::vector<Line3> lines;
	std::vector<Conic3> conics;
	bool has_grasp = false;
	Grasp grasp;
	std::vector<Clique> cliques;
};

}  // namespace mrolr::model
