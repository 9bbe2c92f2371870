#pragma once
/** Small builder for wire-frames in code: lines, polylines, boxes and circle arcs with consecutive
 * ids. Used by SyntheticObjects. */

#include <mrolr/model/WireFrame.h>

#include <string>
#include <vector>

namespace mrolr::recog
{
class WireFrameBuilder
{
 public:
	explicit WireFrameBuilder(std::string name);
	WireFrameBuilder& line(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
	/** Consecutive segments through @p pts; closed adds the segment back to the first point. */
	WireFrameBuilder& polyline(const std::vector<Eigen::Vector3d>& pts, bool closed);
	/** The 12 edges of the box [lo, hi] (axis-aligned in O). */
	WireFrameBuilder& box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
	/** Circle arc of radius r (mm) about @p centre with plane normal @p normal, from t1 to t2 (rad)
	 * measured from @p major. */
	WireFrameBuilder& arc(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
	                      const Eigen::Vector3d& major, double r, double t1, double t2);
	WireFrameBuilder& circle(const Eigen::Vector3d& centre, double r);  ///< full, normal +z
	model::WireFrame build() const { return wf_; }

 private:
	model::WireFrame wf_;
	int next_id_ = 1;
};

}  // namespace mrolr::recog
