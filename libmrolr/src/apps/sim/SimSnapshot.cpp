#include "SimCommon.h"

#include <mrolr/apps/SimApp.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/SceneWireFrame.h>
#include <mrolr/sim/Textures.h>

#include <filesystem>
#include <fstream>
#include <ostream>

namespace mrolr::apps
{
using namespace simdetail;
namespace fs = std::filesystem;

int SimApp::runSnapshot(std::ostream&)
{
	const auto w = world::World::load(world_path);
	const geometry::BiSightHead head(geometry::BiSightOptions::fromFile(bisight_path));
	const auto lab = sim::buildLabScene(w, w.patches.empty());
	sim::StereoRenderer renderer(head, renderOptions(sim_config_path));
	const Eigen::Vector3d xv(pose_zxphi_deg[0], pose_zxphi_deg[1], pose_zxphi_deg[2] * M_PI / 180);
	const double d = M_PI / 180;
	const geometry::HeadAngles a{head_deg[0] * d, head_deg[1] * d, head_deg[2] * d,
	                             head_deg[3] * d};
	head.checkJointLimits(a);
	const auto f =
	    renderer.render(*lab.scene, geometry::T_C0inW(xv, head.options().head_height_m), a);
	fs::create_directories(out_path);
	const auto p = [&](const std::string& n) { return (fs::path(out_path) / n).string(); };
	saveImage(f.left, p("left.png"));
	saveImage(f.right, p("right.png"));
	saveDepthPng(f.depth_left_m, p("depth_left_mm.png"));
	saveDepthPng(f.depth_right_m, p("depth_right_mm.png"));
	savePair(f.left, f.right, p("pair.png"));
	std::ofstream(p("truth.json")) << truthJson(w, head, xv, a, f).dump(2) << "\n";
	// exact wire-frame of the objects in the left camera (mrolr-model stats --truth --depth)
	model::saveWireFrame(sim::tableSceneInCamera(w, lab.shapes, f.T_LinW, sim::SceneParts::Objects),
	                     p("truth_left.wf"));
	files_written = {p("left.png"),           p("right.png"),  p("pair.png"),
	                 p("depth_left_mm.png"),  p("depth_right_mm.png"),
	                 p("truth.json"),         p("truth_left.wf")};
	frames_written = 1;
	render_s = f.render_s;
	return 0;
}

int SimApp::runScene3d(std::ostream&)
{
	const auto w = world::World::load(world_path);
	const auto lab = sim::buildLabScene(w, true);
	if (!lab.scene->saveToFile(scene3d_path))
		throw std::runtime_error("cannot write " + scene3d_path);
	files_written = {scene3d_path};
	return 0;
}

int SimApp::runMakeTextures(std::ostream&)
{
	fs::create_directories(textures_dir);
	auto save = [&](const std::string& name, const std::string& pattern, unsigned seed)
	{
		const std::string path = (fs::path(textures_dir) / (name + ".png")).string();
		saveImage(sim::makeProceduralTexture(pattern, seed), path);
		files_written.push_back(path);
	};
	save("fire_sign", "fire_sign", 0);
	save("light", "light", 0);
	save("checker", "checker", 2);
	for (unsigned i = 1; i <= 9; ++i) save("poster_" + std::to_string(i), "poster", i);
	return 0;
}

}  // namespace mrolr::apps
