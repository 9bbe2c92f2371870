// mission.rawlog and the whole set of a run's outputs.
#include <mrolr/eval/MissionEval.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/MissionOutputs.h>

#include <filesystem>
#include <fstream>

namespace mrolr::eval
{
namespace
{
io::RawlogRecord recordOf(const mission::PathSample& s)
{
	io::RawlogRecord rec;
	rec.time_s = s.time_s;
	rec.odometry_zxphi = s.odometry;
	rec.ticks_right = s.ticks_right, rec.ticks_left = s.ticks_left;
	return rec;
}

/** The record of a stereo shot: images, intrinsics and camera poses on the vehicle (as
 * apps/sim's recording writes them). */
io::RawlogRecord recordOf(const mission::StereoShot& shot, const geometry::BiSightHead& head)
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

/** The true pose at the base's time @p t, when the truth has a step then. */
std::optional<Eigen::Vector3d> trueAt(const MissionTruth* truth, double t)
{
	if (!truth) return std::nullopt;
	for (auto it = truth->steps.rbegin(); it != truth->steps.rend(); ++it)
		if (std::abs(it->time_s - t) < 1e-6) return it->xv_zxphi;
	return std::nullopt;
}
}  // namespace

void writeRawlog(const mission::MissionResult& r, const mission::MissionOptions& o,
                 const MissionTruth* truth, const std::string& path)
{
	io::RawlogWriter w(path);
	const geometry::BiSightHead head(o.bisight);
	size_t k = 0;
	for (const auto& s : r.path)
	{
		for (; k < r.shots.size() && r.shots[k].state.time_s <= s.time_s; ++k)
			w.write(recordOf(r.shots[k], head));
		auto rec = recordOf(s);
		rec.true_zxphi = trueAt(truth, s.device_time_s);
		w.write(rec);
	}
	for (; k < r.shots.size(); ++k) w.write(recordOf(r.shots[k], head));
}

WrittenOutputs writeMissionOutputs(const mission::MissionResult& r,
                                   const mission::MissionOptions& o, const MissionTruth* truth,
                                   const std::string& dir)
{
	std::filesystem::create_directories(dir);
	const auto f = [&](const std::string& n) { return (std::filesystem::path(dir) / n).string(); };
	WrittenOutputs out;
	out.report = mission::reportJson(r, o);
	if (truth) evaluateMission(out.report, *truth);
	std::ofstream(f("report.json")) << out.report.dump(2) << "\n";
	std::ofstream(f("report.md")) << mission::reportMarkdown(out.report);
	writeTrajectoryPng(r, o, truth, f("trajectory.png"));
	writeScene3D(r, o, truth, f("mission.3Dscene"));
	writeRawlog(r, o, truth, f("mission.rawlog"));
	out.files = {f("report.json"), f("report.md"), f("trajectory.png"), f("mission.3Dscene"),
	             f("mission.rawlog")};
	return out;
}

}  // namespace mrolr::eval
