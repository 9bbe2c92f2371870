// trajectory.png, mission.3Dscene and mission.rawlog of a mission.
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/model/ModelRender.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/world/ObjectShape.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/opengl/CEllipsoid3D.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <fstream>

namespace mrolr::mission
{
namespace
{
struct TopView
{
	double scale = 100;  ///< pixels per metre
	Eigen::Vector3d lo, hi;
	cv::Point px(double z, double x) const
	{
		return {static_cast<int>((hi.x() - x) * scale), static_cast<int>((hi.z() - z) * scale)};
	}
};

void drawPath(cv::Mat& img, const TopView& v, const std::vector<PathSample>& path,
              Eigen::Vector3d PathSample::*field, const cv::Scalar& colour)
{
	for (size_t i = 1; i < path.size(); ++i)
	{
		const auto& a = path[i - 1].*field;
		const auto& b = path[i].*field;
		cv::line(img, v.px(a.x(), a.y()), v.px(b.x(), b.y()), colour, 2, cv::LINE_AA);
	}
}

/** A footprint centred at (z, x) in W, turned by yaw, @p depth along its z, @p length along x. */
void drawFootprint(cv::Mat& img, const TopView& v, double z, double x, double yaw_deg, double depth,
                   double length, const cv::Scalar& colour)
{
	const double yaw = yaw_deg * M_PI / 180.0;
	const Eigen::Vector2d az(std::cos(yaw), std::sin(yaw)), ax(-std::sin(yaw), std::cos(yaw));
	std::vector<cv::Point> pts;
	for (auto [sz, sx] : {std::pair{-1, -1}, {-1, 1}, {1, 1}, {1, -1}})
	{
		const Eigen::Vector2d c =
		    Eigen::Vector2d(z, x) + 0.5 * (sz * depth * az + sx * length * ax);
		pts.push_back(v.px(c.x(), c.y()));
	}
	cv::fillConvexPoly(img, pts, colour);
}

void drawTables(cv::Mat& img, const TopView& v, const world::World& w)
{
	for (const auto& t : w.tables)
		drawFootprint(img, v, t.z_m, t.x_m, t.yaw_deg, t.depth_m, t.length_m, {90, 90, 90});
	for (const auto& o : w.obstacles)
		drawFootprint(img, v, o.z_m, o.x_m, o.yaw_deg, o.size_m.z(), o.size_m.x(), {60, 110, 160});
}

/** Obstacle mode's inserted waypoints (W) as diamonds. */
void drawInsertedWaypoints(cv::Mat& img, const TopView& v, const ObstacleReport& r)
{
	for (const auto& e : r.events)
		for (const auto& p : e.via_zx_inW)
			cv::drawMarker(img, v.px(p.x(), p.y()), {0, 120, 255}, cv::MARKER_DIAMOND, 12, 2);
}

void drawLegend(cv::Mat& img)
{
	const std::pair<const char*, cv::Scalar> items[] = {{"true path", {0, 160, 0}},
	                                                    {"estimate", {200, 0, 0}},
	                                                    {"dead reckoning", {0, 0, 220}},
	                                                    {"landmark (true)", {0, 0, 0}},
	                                                    {"landmark (mapped)", {200, 0, 200}}};
	int y = 20;
	for (const auto& [text, colour] : items)
	{
		cv::putText(img, text, {10, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
		y += 20;
	}
}
}  // namespace

void writeTrajectoryPng(const MissionResult& r, const MissionOptions& o, const std::string& path)
{
	TopView v;
	v.lo = o.world.room.min_m, v.hi = o.world.room.max_m;
	cv::Mat img(static_cast<int>((v.hi.z() - v.lo.z()) * v.scale),
	            static_cast<int>((v.hi.x() - v.lo.x()) * v.scale), CV_8UC3,
	            cv::Scalar(255, 255, 255));
	drawTables(img, v, o.world);
	for (const auto& l : o.world.landmarks)
		cv::drawMarker(img, v.px(l.p_LinW.z(), l.p_LinW.x()), {0, 0, 0}, cv::MARKER_SQUARE, 8, 2);
	for (const auto& m : r.map)
		cv::drawMarker(img, v.px(m.p_FinW.z(), m.p_FinW.x()), {200, 0, 200}, cv::MARKER_CROSS, 12,
		               2);
	drawPath(img, v, r.path, &PathSample::odometry, {0, 0, 220});
	drawPath(img, v, r.path, &PathSample::estimate, {200, 0, 0});
	drawPath(img, v, r.path, &PathSample::truth, {0, 160, 0});
	drawInsertedWaypoints(img, v, r.obstacle);
	for (const auto& [name, obj] : r.final_objects)
	{
		const auto p = obj.T_OinW.translation();
		cv::circle(img, v.px(p.z(), p.x()), 4, {0, 140, 255}, -1);
	}
	drawLegend(img);
	if (!cv::imwrite(path, img)) throw std::runtime_error("cannot write " + path);
}

namespace
{
mrpt::opengl::CSetOfLines::Ptr pathLines(const std::vector<PathSample>& path,
                                         Eigen::Vector3d PathSample::*field, float r, float g,
                                         float b, const std::string& name)
{
	auto lines = mrpt::opengl::CSetOfLines::Create();
	lines->setName(name);
	lines->setColor(r, g, b);
	lines->setLineWidth(3);
	for (size_t i = 1; i < path.size(); ++i)
	{
		const auto& a = path[i - 1].*field;
		const auto& c = path[i].*field;
		lines->appendLine(a.x(), a.y(), 0.02, c.x(), c.y(), 0.02);
	}
	return lines;
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

void addRecognisedAndArm(mrpt::opengl::COpenGLScene& scene, const MissionResult& r,
                         const MissionOptions& o, const model::WireFrame& target)
{
	if (!r.found) return;
	// Drawn from the true head centre at the station where it was recognised (the dock).
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(r.search_xv_true, o.bisight.head_height_m);
	Eigen::Isometry3d T_OinC0 = r.search.T_OinC0;
	T_OinC0.translation() /= 1000.0;
	const Eigen::Isometry3d T_OinW = T_C0inW * T_OinC0;
	auto obj = model::wireFrameObject(target);
	obj->setScale(0.001f);  // the model is in mm
	obj->setName("recognised." + r.target);
	obj->setPose(geometry::poseToMrpt(T_OinW));
	scene.insert(obj);
	if (!r.retrieval.attempted) return;
	arm::RtxKinematics kin(o.rtx);
	auto chain = kin.chain(r.retrieval.joints, 0.001);
	auto gl = mrpt::opengl::CSetOfObjects::Create();
	chain.getAs3DObject(gl);
	Eigen::Isometry3d T_C0inA = o.dock.T_C0inA;
	T_C0inA.translation() /= 1000.0;
	gl->setName("arm");
	gl->setPose(geometry::poseToMrpt(T_C0inW * T_C0inA.inverse()));
	scene.insert(gl);
}
}  // namespace

void writeScene3D(const MissionResult& r, const MissionOptions& o, const std::string& path)
{
	auto lab = sim::buildLabScene(o.world);
	auto& scene = *lab.scene;
	for (const auto& [name, obj] : r.final_objects)
		if (auto gl = scene.getByName("object." + name))
			gl->setPose(geometry::cameraPoseToMrpt(obj.T_OinW));
	scene.insert(pathLines(r.path, &PathSample::truth, 0, 0.7f, 0, "path.true"));
	scene.insert(pathLines(r.path, &PathSample::estimate, 0, 0, 0.9f, "path.estimate"));
	scene.insert(pathLines(r.path, &PathSample::odometry, 0.9f, 0, 0, "path.dead_reckoning"));
	addMap(scene, r.map);
	addRecognisedAndArm(scene, r, o,
	                    sim::objectWireFrame(world::ObjectShape::load(o.target_model_file)));
	if (!scene.saveToFile(path)) throw std::runtime_error("cannot write " + path);
}

namespace
{
io::RawlogRecord recordOf(const PathSample& s)
{
	io::RawlogRecord rec;
	rec.time_s = s.time_s;
	rec.odometry_zxphi = s.odometry;
	rec.ticks_right = s.ticks_right, rec.ticks_left = s.ticks_left;
	rec.true_zxphi = s.truth;
	return rec;
}

/** The record of a stereo shot: images, intrinsics and camera poses on the vehicle (as
 * apps/sim's recording writes them). */
io::RawlogRecord recordOf(const StereoShot& shot, const geometry::BiSightHead& head)
{
	auto rec = recordOf(shot.state);
	const auto& a = shot.angles;
	rec.head_rad = {a.pan, a.tilt, a.verg_left, a.verg_right};
	rec.has_stereo = true;
	rec.left = shot.left, rec.right = shot.right;
	rec.camera = head.camera().toTCamera();
	const Eigen::Isometry3d T_C0inV = geometry::T_C0inW({0, 0, 0}, head.options().head_height_m);
	const auto L = head.T_CamCvInC0(geometry::Side::Left, a);
	rec.T_LcvInVehicle = geometry::cameraPoseToMrpt(T_C0inV * L)
	                         .getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>()
	                         .asEigen();
	rec.T_RcvInLcv = L.inverse() * head.T_CamCvInC0(geometry::Side::Right, a);
	return rec;
}
}  // namespace

void writeRawlog(const MissionResult& r, const MissionOptions& o, const std::string& path)
{
	io::RawlogWriter w(path);
	const geometry::BiSightHead head(o.bisight);
	size_t k = 0;
	for (const auto& s : r.path)
	{
		for (; k < r.shots.size() && r.shots[k].state.time_s <= s.time_s; ++k)
			w.write(recordOf(r.shots[k], head));
		w.write(recordOf(s));
	}
	for (; k < r.shots.size(); ++k) w.write(recordOf(r.shots[k], head));
}

std::vector<std::string> writeOutputs(const MissionResult& r, const MissionOptions& o,
                                      const std::string& dir)
{
	std::filesystem::create_directories(dir);
	const auto f = [&](const std::string& n) { return (std::filesystem::path(dir) / n).string(); };
	std::ofstream(f("report.json")) << reportJson(r, o).dump(2) << "\n";
	std::ofstream(f("report.md")) << reportMarkdown(r, o);
	writeTrajectoryPng(r, o, f("trajectory.png"));
	writeScene3D(r, o, f("mission.3Dscene"));
	writeRawlog(r, o, f("mission.rawlog"));
	return {f("report.json"), f("report.md"), f("trajectory.png"), f("mission.3Dscene"),
	        f("mission.rawlog")};
}

}  // namespace mrolr::mission
