// mission.3Dscene: the run in 3D for SceneViewer3D.
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/model/ModelRender.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/SceneBuilder.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CEllipsoid3D.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <filesystem>

namespace mrolr::eval
{
namespace
{
using mission::MappedLandmark;

mrpt::opengl::CSetOfLines::Ptr pathLines(const std::vector<Eigen::Vector3d>& path, float r,
                                         float g, float b, const std::string& name)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName(name);
	lines->setColor(r, g, b);
	lines->setLineWidth(3);
	for (size_t i = 1; i < path.size(); ++i)
		lines->appendLine(path[i - 1].x(), path[i - 1].y(), 0.02, path[i].x(), path[i].y(), 0.02);
	return lines;
}

std::vector<Eigen::Vector3d> pathOf(const std::vector<mission::PathSample>& path,
                                    Eigen::Vector3d mission::PathSample::*field)
{
	std::vector<Eigen::Vector3d> out;
	for (const auto& s : path) out.push_back(s.*field);
	return out;
}

void addMap(mrpt::opengl::COpenGLScene& scene, const std::vector<MappedLandmark>& map)
{
	const Eigen::Matrix3d P = geometry::R_mrptFromThesis();
	for (const auto& m : map)
	{
		auto e = mrpt::opengl::CEllipsoid3D::Create();
		e->setName("map." + m.label);
		e->setQuantiles(2.7955);  // 95 % of a 3-DOF Gaussian: sqrt(chi2_3(0.95))
		Eigen::Matrix3d cov = P * m.P * P.transpose() + 1e-8 * Eigen::Matrix3d::Identity();
		e->setCovMatrix(mrpt::math::CMatrixDouble33(cov));
		const auto p = geometry::pointToMrpt(m.p_FinW);
		e->setLocation(p.x, p.y, p.z);
		e->setColor(0.8f, 0.f, 0.8f, 0.6f);
		scene.insert(e);
	}
}

/** The plan's tables as boxes (MRPT axes: x = thesis z, y = thesis x, z up). */
void addPlanTables(mrpt::opengl::COpenGLScene& scene, const mission::MissionOptions& o)
{
	for (const auto& t : o.plan.tables)
	{
		auto box = mrpt::opengl::CBox::Create(
		    mrpt::math::TPoint3D(-t.depth_m / 2, -t.length_m / 2, 0),
		    mrpt::math::TPoint3D(t.depth_m / 2, t.length_m / 2, t.top_height_m));
		box->setName("plan.table." + t.name);
		box->setPose(mrpt::poses::CPose3D(t.z_m, t.x_m, 0, t.yaw_deg * M_PI / 180.0, 0, 0));
		box->setColor(0.4f, 0.4f, 0.4f, 0.5f);
		scene.insert(box);
	}
}

void addRecognisedAndArm(mrpt::opengl::COpenGLScene& scene, const mission::MissionResult& r,
                         const mission::MissionOptions& o)
{
	if (!r.found) return;
	// Placed where the robot believed it was: its estimate at the station.
	const Eigen::Isometry3d T_C0inW =
	    geometry::T_C0inW(r.search_xv_estimate, o.bisight.head_height_m);
	auto obj = model::wireFrameObject(
	    model::loadWireFrame((std::filesystem::path(o.models_dir) / (o.target + ".wf")).string()));
	obj->setScale(0.001f);  // the model is in mm
	obj->setName("recognised." + r.target);
	obj->setPose(geometry::poseToMrpt(T_C0inW * geometry::inMetres(r.search.T_OinC0_mm)));
	scene.insert(obj);
	if (!r.retrieval.attempted) return;
	arm::RtxKinematics kin(o.rtx);
	auto chain = kin.chain(r.retrieval.joints, 0.001);
	auto gl = mrpt::opengl::CSetOfObjects::Create();
	chain.getAs3DObject(gl);
	gl->setName("arm");
	gl->setPose(geometry::poseToMrpt(T_C0inW * geometry::inMetres(o.dock.T_C0inA).inverse()));
	scene.insert(gl);
}
}  // namespace

void writeScene3D(const mission::MissionResult& r, const mission::MissionOptions& o,
                  const MissionTruth* truth, const std::string& path)
{
	mrpt::opengl::COpenGLScene::Ptr scene;
	if (truth && truth->world)
	{
		scene = sim::buildLabScene(*truth->world).scene;
		for (const auto& obj : truth->objects)
			if (auto gl = scene->getByName("object." + obj.name))
				gl->setPose(geometry::cameraPoseToMrpt(obj.T_OinW));
		std::vector<Eigen::Vector3d> true_path;
		for (const auto& s : truth->steps) true_path.push_back(s.xv_zxphi);
		scene->insert(pathLines(true_path, 0, 0.7f, 0, "path.true"));
	}
	else
	{
		scene = mrpt::opengl::COpenGLScene::Create();
		addPlanTables(*scene, o);
	}
	scene->insert(pathLines(pathOf(r.path, &mission::PathSample::estimate), 0, 0, 0.9f,
	                        "path.estimate"));
	scene->insert(pathLines(pathOf(r.path, &mission::PathSample::odometry), 0.9f, 0, 0,
	                        "path.dead_reckoning"));
	addMap(*scene, r.map);
	addRecognisedAndArm(*scene, r, o);
	if (!scene->saveToFile(path)) throw std::runtime_error("cannot write " + path);
}

}  // namespace mrolr::eval
