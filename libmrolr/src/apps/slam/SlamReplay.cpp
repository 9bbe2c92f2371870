// mrolr-slam --rawlog: vision-driven EKF-SLAM on a run recorded by mrolr-sim. The head cannot be
// steered in a replay: the recorded odometry drives the prediction and features are acquired and
// measured in the recorded stereo pairs at the recorded head angles.
#include <mrolr/apps/OdometryControl.h>
#include <mrolr/apps/SlamApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/world/World.h>
#include "LiveHeads.h"
#include "SlamSetup.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace mrolr::apps
{
namespace
{
/** The recording must have been made with the head model of the configuration. */
void requireSameCamera(const io::RawlogRecord& r, const geometry::BiSightHead& head,
                       const std::string& path, size_t k)
{
	const auto& cam = head.camera();
	const auto& rec = r.camera;
	const bool same =
	    std::abs(rec.fx() - cam.focal_px_u) < 1e-3 && std::abs(rec.fy() - cam.focal_px_v) < 1e-3 &&
	    std::abs(rec.cx() - cam.u0_px) < 1e-3 && std::abs(rec.cy() - cam.v0_px) < 1e-3 &&
	    int(r.left.getWidth()) == cam.width_px && int(r.left.getHeight()) == cam.height_px;
	if (!same)
		throw std::runtime_error(path + ": record " + std::to_string(k) +
		                         ": the recorded camera (intrinsics or image size) differs from "
		                         "the bisight configuration of --config");
}

vision::StereoImages imagesOf(const io::RawlogRecord& r)
{
	const auto& h = r.head_rad;
	return {toGray(r.left), toGray(r.right), geometry::HeadAngles{h[0], h[1], h[2], h[3]}};
}

std::vector<TrueLandmark> landmarksOf(const std::string& world_path)
{
	std::vector<TrueLandmark> out;
	if (world_path.empty()) return out;
	for (const auto& l : world::World::load(world_path).landmarks)
		out.push_back({l.name, l.p_LinW});
	return out;
}
}  // namespace

void SlamApp::runReplay()
{
	const SlamSetup s = loadSetup(config_path);
	true_landmarks = landmarksOf(world_path);
	run_title = "mrolr-slam: replay of '" +
	            std::filesystem::path(rawlog_path).filename().string() + "'";
	const std::vector<io::RawlogRecord> records = io::readRawlog(rawlog_path);
	if (records.size() < 2)
		throw std::runtime_error(rawlog_path + ": a replay needs at least 2 records");
	const geometry::BiSightHead head(s.bisight);
	const base::LabmateModel model(s.labmate);
	slam::ActiveSlamFilter filter(s.slam, model);
	filter.reset(records.front().odometry_zxphi);  // the start pose defines W
	vision::VisualSlam vslam(filter, head, s.vision, model);
	for (size_t k = 0; k < records.size(); ++k)
	{
		const io::RawlogRecord& r = records[k];
		base::WheelControl u;
		if (k > 0)
		{
			const double dt = r.time_s - records[k - 1].time_s;
			if (!(dt > 0))
				throw std::runtime_error(rawlog_path + ": record " + std::to_string(k) +
				                         ": time does not increase");
			u = controlFromOdometry(records[k - 1].odometry_zxphi, r.odometry_zxphi, dt,
			                        s.labmate.wheel_half_separation_m);
		}
		if (r.has_stereo) requireSameCamera(r, head, rawlog_path, k);
		const vision::StereoImages images = r.has_stereo ? imagesOf(r) : vision::StereoImages{};
		auto recs = vslam.replayFrame(u, r.has_stereo ? &images : nullptr);
		if (!r.true_zxphi)
			throw std::runtime_error(rawlog_path + ": record " + std::to_string(k) +
			                         ": no GROUND_TRUTH (needed for the replay's errors)");
		steps.push_back({*r.true_zxphi, filter.vehicle(), r.odometry_zxphi,
		                 filter.vehicleCovariance().diagonal(), std::move(recs)});
	}
	recordMap(filter, vslam);
	summary.selection = "replay";  // every mapped feature in the recorded view is measured
}

}  // namespace mrolr::apps
