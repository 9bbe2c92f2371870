// The RTX drawn in the lab's scene at its current joints.
#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/ArmVisual.h>

#include <mrpt/img/CImage.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CTexturedPlane.h>
#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

namespace mrolr::sim
{
namespace
{
constexpr double kMm = 1e-3;
constexpr float kArmGrey = 0.3f, kFingerGrey = 0.45f;
constexpr int kCellPx = 16;  ///< texture pixels per ArUco cell

/** An axis-aligned box of the frame it is inserted in, corners in mm. */
mrpt::opengl::CBox::Ptr box(const Eigen::Vector3d& lo_mm, const Eigen::Vector3d& hi_mm, float grey)
{
	auto b = mrpt::opengl::CBox::Create(
	    mrpt::math::TPoint3D(lo_mm.x() * kMm, lo_mm.y() * kMm, lo_mm.z() * kMm),
	    mrpt::math::TPoint3D(hi_mm.x() * kMm, hi_mm.y() * kMm, hi_mm.z() * kMm));
	b->setColor(grey, grey, grey);
	return b;
}

/** The ArUco code (4×4 cells and a one-cell black border) inside a one-cell white quiet zone. */
mrpt::img::CImage markerTexture(int id)
{
	const auto dict = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50);
	cv::Mat code, grey;
	cv::aruco::drawMarker(dict, id, 6 * kCellPx, code, 1);
	cv::flip(code, code, 0);  // MRPT maps image rows bottom-up onto the plane
	cv::copyMakeBorder(code, grey, kCellPx, kCellPx, kCellPx, kCellPx, cv::BORDER_CONSTANT, 255);
	cv::Mat bgr;
	cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
	return mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
}

/** The marker plate in G: its plane x_G = p.x, local x along y_G, local y along z_G. */
mrpt::opengl::CTexturedPlane::Ptr markerPlate(const arm::MarkerOptions& m)
{
	const double half_m = m.plateHalfMm() * kMm;
	auto p = mrpt::opengl::CTexturedPlane::Create(-half_m, half_m, -half_m, half_m);
	p->assignImage(markerTexture(m.aruco_id));
	// the pose within G itself (the set it joins is posed in G's own axes)
	mrpt::math::CMatrixDouble44 H = mrpt::math::CMatrixDouble44::Identity();
	const Eigen::Matrix3d R = (Eigen::Matrix3d() << Eigen::Vector3d::UnitY(),
	                           Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX())
	                              .finished();
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j) H(i, j) = R(i, j);
		H(i, 3) = m.p_MinG_mm[i] * kMm;
	}
	p->setPose(mrpt::poses::CPose3D(H));
	return p;
}

Eigen::Isometry3d metres(Eigen::Isometry3d T_mm)
{
	T_mm.translation() *= kMm;
	return T_mm;
}
}  // namespace

ArmVisual::ArmVisual(const arm::RtxOptions& rtx, const arm::GraspFeasibilityOptions& grip,
                     double finger_thickness_mm, const arm::MarkerOptions& marker)
    : kin_(rtx), root_(mrpt::opengl::CSetOfObjects::Create())
{
	root_->setName("arm");
	for (auto& f : frames_) root_->insert(f = mrpt::opengl::CSetOfObjects::Create());
	for (auto& f : fingers_) root_->insert(f = mrpt::opengl::CSetOfObjects::Create());
	for (const auto& b : arm::rtxBody(rtx, grip, marker))
		frames_.at(static_cast<size_t>(b.frame))->insert(box(b.lo_mm, b.hi_mm, kArmGrey));
	frames_[6]->insert(markerPlate(marker));
	// The plates, in their own frames (shifted along y_G by the separation at each update).
	const double w = grip.finger_width_mm / 2, h = grip.finger_length_mm / 2;
	fingers_[0]->insert(box({-w, 0, -h}, {w, finger_thickness_mm, h}, kFingerGrey));
	fingers_[1]->insert(box({-w, -finger_thickness_mm, -h}, {w, 0, h}, kFingerGrey));
}

void ArmVisual::update(const Eigen::Isometry3d& T_AinW_m, const arm::RtxJoints& j,
                       double separation_mm)
{
	const auto T0i = kin_.linkFrames(j);
	for (size_t i = 0; i < frames_.size() && i < T0i.size(); ++i)
		frames_[i]->setPose(geometry::cameraPoseToMrpt(T_AinW_m * metres(T0i[i])));
	const Eigen::Isometry3d T_GinW = T_AinW_m * metres(T0i.back());
	for (int side = 0; side < 2; ++side)
	{
		const double y_mm = (side == 0 ? 1 : -1) * separation_mm / 2;
		fingers_[side]->setPose(geometry::cameraPoseToMrpt(
		    T_GinW * Eigen::Translation3d(0, y_mm * kMm, 0)));
	}
}

}  // namespace mrolr::sim
