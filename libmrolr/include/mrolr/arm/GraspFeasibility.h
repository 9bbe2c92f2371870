#pragma once
/** Can the RTX take the object at this grasp? (thesis 6.8 module 2 and 7.2.2: object dimensions
 * against the gripper opening; reach.) The gripper G is modelled as two fingers of length
 * finger_length_mm and width finger_width_mm centred on the grasp point, closing along y_G and
 * approaching along z_G from approach_distance_mm back. Checks:
 *  - reach: the analytic IK has a solution within the joint limits (≈ 500 mm wrist radius);
 *  - opening: the object points the open fingers straddle on the way in (|x_G| ≤ width/2, z_G
 *    from −(length/2 + approach) down to the fingertips at +length/2) lie within
 *    ±(opening/2 − margin) along y_G; a wire-frame has only edges, so this is the width of the
 *    edges that pass between the fingers;
 *  - table: the open fingertips stay table_clearance_mm above the table plane z_A = table_z_mm
 *    along the approach;
 *  - neighbours: no neighbour point inside the open gripper's swept box grown by
 *    neighbour_clearance_mm. Lengths in mm, points in the arm base A. */

#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::arm
{
/** Section [arm_grasp] of config/arm_rtx.ini. The defaults are assumptions (the thesis gives no
 * gripper dimensions). */
struct GraspFeasibilityOptions
{
	double gripper_opening_max_mm = 90;
	double grip_margin_mm = 5;
	double finger_length_mm = 40;
	double finger_width_mm = 20;
	double approach_distance_mm = 100;
	double table_clearance_mm = 10;
	double neighbour_clearance_mm = 20;
	double sample_step_mm = 2;  ///< spacing of points sampled on lines and conics

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

struct GraspCheck
{
	std::vector<IkSolution> solutions;
	double width_mm = 0;            ///< extent along y_G of the object points between the fingers
	double table_clearance_mm = 0;  ///< lowest open fingertip above the table along the approach
	int neighbour_points_in_path = 0;
	std::vector<std::string> reasons;  ///< one line per failed check; empty when feasible
	bool feasible() const { return reasons.empty(); }
};

/** Points every @p step_mm along the lines and conic arcs of @p wf, moved by @p T (mm). */
std::vector<Eigen::Vector3d> sampleWireFrame(const model::WireFrame& wf, const Eigen::Isometry3d& T,
                                             double step_mm);

/** Runs every check for the gripper pose T_GinA. */
GraspCheck checkGrasp(const Eigen::Isometry3d& T_GinA,
                      const std::vector<Eigen::Vector3d>& object_points_A,
                      const std::vector<Eigen::Vector3d>& neighbour_points_A, double table_z_mm,
                      const AnalyticIk& ik, const GraspFeasibilityOptions& options);

}  // namespace mrolr::arm
