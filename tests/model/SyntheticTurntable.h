#pragma once
// Test helper: a rendered turntable directory (turntable.ini, calibration, 8 stereo views and the
// exact model) of a 100×70×60 mm box, in the format of docs/model.md.

#include "SyntheticScenes.h"

#include <mrolr/model/WireFrameIO.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>

namespace mrolr::model::test
{
inline const Eigen::Vector3d kBoxSize(100, 70, 60);  // mm, on the turntable, centred on its axis

/** Pose of the left camera in the turntable frame T: 650 mm away, 380 mm up, looking at the box. */
inline Eigen::Isometry3d cameraInTurntable()
{
	const Eigen::Vector3d cam(-650, -60, 380), target(0, 0, 30), up = Eigen::Vector3d::UnitZ();
	const Eigen::Vector3d z = (target - cam).normalized(), x = up.cross(z).normalized(),
	                      y = z.cross(x);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << x, y, z;
	T.translation() = cam;
	return T;
}

inline Eigen::Vector3d corner(int i)
{
	return {(i & 1 ? 0.5 : -0.5) * kBoxSize.x(), (i & 2 ? 0.5 : -0.5) * kBoxSize.y(),
	        (i & 4 ? 1.0 : 0.0) * kBoxSize.z()};
}

inline WireFrame boxTruth()
{
	WireFrame wf;
	for (int i = 0; i < 8; ++i)
		for (int bit : {1, 2, 4})
			if (!(i & bit))
				wf.lines.push_back(
				    {static_cast<int>(wf.lines.size()) + 1, corner(i), corner(i | bit)});
	return wf;
}

/** The box's faces (outward axis, corner indices in order) and grey levels. */
inline std::vector<std::pair<Eigen::Vector3d, std::vector<int>>> boxFaces()
{
	return {{{-1, 0, 0}, {0, 2, 6, 4}},
	        {{1, 0, 0}, {1, 3, 7, 5}},
	        {{0, -1, 0}, {0, 1, 5, 4}},
	        {{0, 1, 0}, {2, 3, 7, 6}},
	        {{0, 0, 1}, {4, 5, 7, 6}}};
}

/** Faces in L of the box turned by angle_deg, back faces culled, over a table plane. */
inline std::vector<stereo::test::Face> viewFaces(double angle_deg)
{
	const Eigen::Isometry3d T_LinT = cameraInTurntable();
	const Eigen::Isometry3d T_OinL =
	    T_LinT.inverse() * Eigen::AngleAxisd(angle_deg * M_PI / 180, Eigen::Vector3d::UnitZ());
	std::vector<stereo::test::Face> faces;
	stereo::test::Face table{{}, 90};
	for (const auto& c :
	     {Eigen::Vector3d(-900, -900, 0), {900, -900, 0}, {900, 900, 0}, {-900, 900, 0}})
		table.outline.push_back(T_OinL * c);
	faces.push_back(table);
	const int greys[] = {200, 150, 175, 120, 235};
	int k = 0;
	for (const auto& [n, idx] : boxFaces())
	{
		const Eigen::Vector3d centre_L =
		    T_OinL * (kBoxSize.cwiseProduct(n) / 2 + Eigen::Vector3d(0, 0, kBoxSize.z() / 2));
		const Eigen::Vector3d n_L = T_OinL.linear() * n;
		stereo::test::Face f{{}, greys[k++]};
		for (int i : idx) f.outline.push_back(T_OinL * corner(i));
		if (n_L.dot(-centre_L) > 0) faces.push_back(f);
	}
	return faces;  // painter's order: table first; a convex box's front faces never overlap
}

/** The box edges visible in the left camera with the box turned by angle_deg (an edge is visible
 * when one of its faces is; the bottom face never is), in frame L. */
inline WireFrame visibleTruthInL(double angle_deg)
{
	const Eigen::Isometry3d T_OinL =
	    cameraInTurntable().inverse() *
	    Eigen::AngleAxisd(angle_deg * M_PI / 180, Eigen::Vector3d::UnitZ());
	WireFrame truth;
	truth.frame = WireFrameFrame::LeftCamera;
	for (const auto& l : boxTruth().lines)
	{
		const Eigen::Vector3d m = (l.p1 + l.p2) / 2;
		bool visible = false;
		for (const auto& [n, idx] : boxFaces())
		{
			const Eigen::Vector3d c =
			    kBoxSize.cwiseProduct(n) / 2 + Eigen::Vector3d(0, 0, kBoxSize.z() / 2);
			const bool on_face = std::abs((m - c).dot(n)) < 1e-6;
			visible |= on_face && (T_OinL.linear() * n).dot(-(T_OinL * c)) > 0;
		}
		if (visible) truth.lines.push_back({l.id, T_OinL * l.p1, T_OinL * l.p2});
	}
	return truth;
}

inline void writeTurntableDir(const std::string& dir)
{
	std::filesystem::create_directories(dir);
	const auto rig = stereo::test::testRig();
	stereo::saveStereoCalibration(rig, dir + "/calib.ini");
	saveWireFrame(boxTruth(), dir + "/box.wf");
	std::ofstream ini(dir + "/turntable.ini");
	ini.precision(17);
	const Eigen::Isometry3d T = cameraInTurntable();
	ini << "[turntable]\nobject = box\ncalib = calib.ini\ntruth = box.wf\nviews = 8\nR_TfromL =";
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) ini << ' ' << T.linear()(r, c);
	ini << "\nt_LinT_mm = " << T.translation().transpose() << "\n";
	for (int v = 0; v < 8; ++v)
	{
		cv::Mat L, R;
		stereo::test::renderPair(viewFaces(45.0 * v), rig, L, R, false);
		const std::string stem = "view_" + std::to_string(v);
		cv::imwrite(dir + "/" + stem + "_left.png", L);
		cv::imwrite(dir + "/" + stem + "_right.png", R);
		ini << "[" << stem << "]\nleft = " << stem << "_left.png\nright = " << stem
		    << "_right.png\nangle_deg = " << 45.0 * v << "\n";
	}
}

}  // namespace mrolr::model::test
