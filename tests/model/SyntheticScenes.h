#pragma once
// Test helper: synthetic stereo scenes (tests/stereo/SyntheticStereo.h) with their exact
// wire-frames in the left camera frame L (mm).

#include "../stereo/SyntheticStereo.h"

#include <mrolr/model/WireFrame.h>

namespace mrolr::model::test
{
using stereo::test::Face;

inline Eigen::Matrix3d rotZYX(double rz_deg, double ry_deg, double rx_deg)
{
	const double k = M_PI / 180;
	return (Eigen::AngleAxisd(rz_deg * k, Eigen::Vector3d::UnitZ()) *
	        Eigen::AngleAxisd(ry_deg * k, Eigen::Vector3d::UnitY()) *
	        Eigen::AngleAxisd(rx_deg * k, Eigen::Vector3d::UnitX()))
	    .toRotationMatrix();
}

inline size_t featureCountOf(const WireFrame& wf)
{
	return wf.lines.size() + wf.conics.size();
}

/** Adds the polygon edges of a face (as lines) to a truth wire-frame. */
inline void addPolygonEdges(const Face& f, WireFrame& wf)
{
	const size_t n = f.outline.size();
	for (size_t i = 0; i < n; ++i)
		wf.lines.push_back(
		    {static_cast<int>(featureCountOf(wf) + 1), f.outline[i], f.outline[(i + 1) % n]});
}

/** Adds a full circle of radius r in the plane (u, v) at c. */
inline void addCircle(const Eigen::Vector3d& c, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                      double r, WireFrame& wf)
{
	Conic3 k;
	k.id = static_cast<int>(featureCountOf(wf) + 1);
	k.centre = c;
	k.major = u;
	k.normal = u.cross(v);
	k.a = k.b = r;
	k.t1 = 0;
	k.t2 = 2 * M_PI;
	wf.conics.push_back(k);
}

/** Two tilted cards and a tilted disc about 1 m in front of the left camera. */
inline std::vector<Face> cardsAndDisc(WireFrame& truth)
{
	truth = WireFrame();
	truth.frame = WireFrameFrame::LeftCamera;
	const Eigen::Matrix3d A = rotZYX(20, 25, 0), B = rotZYX(-25, 30, 15), D = rotZYX(0, 0, 55);
	std::vector<Face> faces{
	    stereo::test::rectangle({160, 40, 1000}, A.col(0), A.col(1), 150, 100, 200),
	    stereo::test::rectangle({-150, -70, 1100}, B.col(0), B.col(1), 160, 120, 150),
	    stereo::test::disc({0, 90, 950}, D.col(0), D.col(1), 50, 230)};
	addPolygonEdges(faces[0], truth);
	addPolygonEdges(faces[1], truth);
	addCircle({0, 90, 950}, D.col(0), D.col(1), 50, truth);
	return faces;
}

}  // namespace mrolr::model::test
