#include <mrolr/geometry/Frames.h>
#include "SlamRecordings.h"

#include <mrpt/opengl/CEllipsoid3D.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>

#include <stdexcept>

namespace mrolr::apps
{
namespace
{
constexpr float kSqrtChi2_3dof_95 = 2.7955f;  ///< 95 % of a 3-DOF Gaussian: √χ²₃(0.95)
constexpr double kPathHeight_m = 0.02;        ///< paths drawn just above the floor

mrpt::opengl::CSetOfLines::Ptr path(const std::vector<SlamStepLog>& steps,
                                    Eigen::Vector3d SlamStepLog::*pose, const std::string& name,
                                    const mrpt::img::TColor& colour)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName(name);
	lines->setColor_u8(colour);
	lines->setLineWidth(3);
	for (size_t k = 1; k < steps.size(); ++k)
	{
		const auto a = geometry::vehicleToMrpt(steps[k - 1].*pose);
		const auto b = geometry::vehicleToMrpt(steps[k].*pose);
		lines->appendLine(a.x(), a.y(), kPathHeight_m, b.x(), b.y(), kPathHeight_m);
	}
	return lines;
}

mrpt::opengl::CEllipsoid3D::Ptr ellipsoid(const MapFeature& f)
{
	const Eigen::Matrix3d R = geometry::R_mrptFromThesis();
	auto e = mrpt::opengl::CEllipsoid3D::Create();
	e->setName("map." + f.label);
	e->setQuantiles(kSqrtChi2_3dof_95);
	// a known feature has zero covariance: a tiny sphere keeps it drawable
	const Eigen::Matrix3d cov = R * f.cov * R.transpose() + 1e-8 * Eigen::Matrix3d::Identity();
	e->setCovMatrix(mrpt::math::CMatrixDouble33(cov));
	const auto p = geometry::pointToMrpt(f.p_FinW);
	e->setLocation(p.x, p.y, p.z);
	e->setColor_u8(f.known ? mrpt::img::TColor(0, 160, 0, 200) : mrpt::img::TColor(220, 0, 0, 160));
	return e;
}

mrpt::opengl::CPointCloud::Ptr truthPoints(const std::vector<TrueLandmark>& truth)
{
	auto cloud = mrpt::opengl::CPointCloud::Create();
	cloud->setName("landmarks.true");
	cloud->setPointSize(6);
	cloud->setColor_u8(mrpt::img::TColor(0, 0, 0));
	for (const auto& l : truth)
	{
		const auto p = geometry::pointToMrpt(l.p_LinW);
		cloud->insertPoint(float(p.x), float(p.y), float(p.z));
	}
	return cloud;
}
}  // namespace

void writeSlamScene(const std::string& file, const std::vector<SlamStepLog>& steps,
                    const std::vector<MapFeature>& map, const std::vector<TrueLandmark>& truth)
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(mrpt::opengl::CGridPlaneXY::Create(-10, 10, -10, 10, 0, 1));
	scene.insert(path(steps, &SlamStepLog::x_true, "path.true", {0, 160, 0}));
	scene.insert(path(steps, &SlamStepLog::x_est, "path.estimate", {220, 0, 0}));
	scene.insert(path(steps, &SlamStepLog::x_dr, "path.dead_reckoning", {0, 0, 220}));
	for (const auto& f : map) scene.insert(ellipsoid(f));
	if (!truth.empty()) scene.insert(truthPoints(truth));
	if (!scene.saveToFile(file)) throw std::runtime_error(file + ": cannot write");
}

}  // namespace mrolr::apps
