#include "SimCommon.h"

#include <mrolr/apps/SimApp.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/sim/SimHead.h>

#include <mrpt/config/CConfigFile.h>

#include <ostream>

namespace mrolr::apps
{
using namespace simdetail;

namespace
{
/** The nearest landmark the head can fixate from the true pose (joint limits, in front). */
bool chooseFixation(const world::World& w, const geometry::BiSightHead& head,
                    const Eigen::Isometry3d& T_C0inW, geometry::HeadAngles& out)
{
	double best = 1e9;
	for (const auto& l : w.landmarks)
	{
		const Eigen::Vector3d p = T_C0inW.inverse() * l.p_LinW;
		if (p.z() <= 0.3 || p.norm() >= best) continue;
		try
		{
			out = head.fixate(p);
			best = p.norm();
		}
		catch (const geometry::GeometryError&)
		{
		}
	}
	return best < 1e9;
}

/** The open-loop route through the waypoints: rotate, translate in steps, rotate (5.6.3, 7.2.1). */
std::vector<base::PlannedStep> planRoute(const world::World& w, const base::LabmateModel& labmate,
                                         const mrpt::config::CConfigFileBase& cfg)
{
	base::TrajectoryOptions to;
	to.loadFromConfigFile(cfg, "trajectory");
	std::vector<base::PlannedStep> steps;
	for (size_t i = 1; i < w.waypoints.size(); ++i)
	{
		const auto& a = w.waypoints[i - 1];
		const auto& b = w.waypoints[i];
		for (const auto& s :
		     base::planLeg({a.z_m, a.x_m, a.phi_rad}, {b.z_m, b.x_m, b.phi_rad}, labmate, to))
			steps.push_back(s);
	}
	return steps;
}

io::RawlogRecord recordOf(const sim::SimBase& base, const sim::SimHead& head,
                          const geometry::BiSightHead& model, bool has_stereo)
{
	io::RawlogRecord r;
	const auto odo = base.odometry();
	r.time_s = odo.time_s;
	r.odometry_zxphi = odo.xv_zxphi;
	r.ticks_right = odo.ticks_right, r.ticks_left = odo.ticks_left;
	r.true_zxphi = base.truePose();
	const auto a = head.angles();
	r.head_rad = {a.pan, a.tilt, a.verg_left, a.verg_right};
	r.has_stereo = has_stereo;
	if (!has_stereo) return r;
	r.left = head.lastFrame().left, r.right = head.lastFrame().right;
	r.camera = model.camera().toTCamera();
	const Eigen::Isometry3d T_C0inV = geometry::T_C0inW({0, 0, 0}, model.options().head_height_m);
	const auto L = model.T_CamCvInC0(geometry::Side::Left, a);
	r.T_LcvInVehicle = geometry::cameraPoseToMrpt(T_C0inV * L)
	                       .getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>()
	                       .asEigen();
	r.T_RcvInLcv = L.inverse() * model.T_CamCvInC0(geometry::Side::Right, a);
	return r;
}
}  // namespace

int SimApp::runRecording(std::ostream& out)
{
	const auto w = world::World::load(world_path);
	if (w.waypoints.size() < 2)
		throw std::runtime_error(world_path + ": needs at least 2 waypoints");
	const geometry::BiSightHead model(geometry::BiSightOptions::fromFile(bisight_path));
	const mrpt::config::CConfigFile labmateCfg(projectFile("config/labmate.ini"));
	base::LabmateOptions lo;
	lo.loadFromConfigFile(labmateCfg, "labmate");
	const base::LabmateModel labmate(lo);
	const auto steps = planRoute(w, labmate, labmateCfg);
	const mrpt::config::CConfigFile simCfg(sim_config_path);
	sim::SimBaseOptions bo;
	bo.loadFromConfigFile(simCfg, "sim_base");
	sim::SimHeadOptions ho;
	ho.loadFromConfigFile(simCfg, "sim_head");
	const auto& wp0 = w.waypoints.front();
	sim::SimBase base(labmate, bo, {wp0.z_m, wp0.x_m, wp0.phi_rad});
	const auto lab = sim::buildLabScene(w, w.patches.empty());
	sim::StereoRenderer renderer(model, renderOptions(sim_config_path));
	const double hh = model.options().head_height_m;
	sim::SimHead head(
	    renderer, *lab.scene, [&] { return geometry::T_C0inW(base.truePose(), hh); }, ho);
	io::RawlogWriter writer(out_path);
	const size_t n = max_steps > 0 ? std::min(steps.size(), size_t(max_steps)) : steps.size();
	auto record = [&](bool grabbed) { writer.write(recordOf(base, head, model, grabbed)); };
	for (size_t k = 0; k <= n; ++k)
	{
		if (k > 0) base.step(steps[k - 1].u);
		geometry::HeadAngles a;
		const bool look = chooseFixation(w, model, geometry::T_C0inW(base.truePose(), hh), a);
		if (look)
		{
			head.moveTo(a);
			head.grab();
			render_s += head.lastFrame().render_s;
		}
		record(look);
		frames_written += look ? 1 : 0;
		if (!json)
			out << "\rstep " << k << "/" << n << " (" << frames_written << " pairs)" << std::flush;
	}
	if (!json) out << "\n";
	odometry_final_error_m = (base.odometry().xv_zxphi - base.truePose()).head<2>().norm();
	files_written = {out_path, writer.imagesDir()};
	return 0;
}

}  // namespace mrolr::apps
