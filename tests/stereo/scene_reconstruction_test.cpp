#include "SyntheticStereo.h"

#include <mrolr/stereo/SceneReconstruction.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <iostream>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
Eigen::Matrix3d rot(double rz_deg, double ry_deg, double rx_deg)
{
	const double k = M_PI / 180;
	return (Eigen::AngleAxisd(rz_deg * k, Eigen::Vector3d::UnitZ()) *
			Eigen::AngleAxisd(ry_deg * k, Eigen::Vector3d::UnitY()) *
			Eigen::AngleAxisd(rx_deg * k, Eigen::Vector3d::UnitX()))
		.toRotationMatrix();
}

std::vector<Face> cardsAndDisc()
{
	const Eigen::Matrix3d A = rot(20, 25, 0), B = rot(-25, 30, 15), D = rot(0, 0, 55);
	return {rectangle({160, 40, 1000}, A.col(0), A.col(1), 150, 100, 200),
		rectangle({-150, -70, 1100}, B.col(0), B.col(1), 160, 120, 150),
		disc({0, 90, 950}, D.col(0), D.col(1), 50, 230)};
}
}  // namespace

TEST(SceneReconstruction, SmokeRun)
{
	const auto rig = testRig();
	cv::Mat L, R;
	renderPair(cardsAndDisc(), rig, L, R);
	cv::imwrite("/tmp/model_scratch/L.png", L);
	cv::imwrite("/tmp/model_scratch/R.png", R);
	const StereoScene s = reconstructScene(L, R, rig, SceneOptions());
	std::cout << s.left_strings << " " << s.right_strings << " " << s.matches << " " << s.strings3d << "\n";
	for (const auto& l : s.lines)
		std::cout << "line " << l.p1.transpose() << " | " << l.p2.transpose() << " rms " << l.rms_mm << " n " << l.edgels << "\n";
	for (const auto& c : s.conics)
		std::cout << "conic " << c.centre.transpose() << " n " << c.normal.transpose() << " a " << c.a << " b " << c.b << " t " << c.t1 << " " << c.t2 << " rms " << c.rms_mm << "\n";
}
