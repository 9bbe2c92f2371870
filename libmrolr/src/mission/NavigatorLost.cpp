// Knowing when it is lost, and finding the map again (landmark_sensor = images).
#include <mrolr/mission/Navigator.h>

#include <chrono>
#include <cmath>
#include <sstream>

namespace mrolr::mission
{
namespace
{
/** The last measurement attempts looked at ... */
constexpr size_t kLostWindow = 9;
/** ... of which at most this many accepted means lost (repeated failed searches). */
constexpr int kLostMaxAccepted = 2;
/** The estimate is too uncertain to steer by beyond these standard deviations. */
constexpr double kLostSigma_m = 0.25;
constexpr double kLostSigma_rad = 8.0 * M_PI / 180.0;
/** After failed searches the robot doubts its estimate by this much (σ: 0.3 m, 10°), twice as
 * much (σ) after each attempt that found nothing, up to kMaxDoubts doublings. */
const Eigen::Matrix3d kDoubt =
    Eigen::Vector3d(0.09, 0.09, std::pow(10.0 * M_PI / 180.0, 2)).asDiagonal();
constexpr int kMaxDoubts = 2;
/** Steps between two attempts to find the map again, known features tried, their range (m). */
constexpr int kRelocaliseEvery = 3;
constexpr int kRelocaliseFeatures = 3;
constexpr double kRelocaliseRange_m = 8.0;
}  // namespace

std::string Navigator::lostReason()
{
	const Eigen::Matrix3d P = filter_.vehicleCovariance();
	const double sigma_m = std::sqrt(P.topLeftCorner<2, 2>().eigenvalues().real().maxCoeff());
	const double sigma_rad = std::sqrt(P(2, 2));
	std::ostringstream s;
	s.precision(2);
	if (sigma_m > kLostSigma_m || sigma_rad > kLostSigma_rad)
		s << std::fixed << "the estimate's uncertainty grew to " << sigma_m << " m, "
		  << sigma_rad * 180 / M_PI << " deg";
	else if (recent_.size() >= kLostWindow &&
	         std::count(recent_.begin(), recent_.end(), true) <= kLostMaxAccepted)
		s << "only " << std::count(recent_.begin(), recent_.end(), true) << " of the last "
		  << recent_.size() << " searches matched";
	return s.str();
}

void Navigator::noteAttempt(bool accepted)
{
	recent_.push_back(accepted);
	while (recent_.size() > kLostWindow) recent_.pop_front();
}

void Navigator::checkLost()
{
	++steps_since_relocalise_;
	if (!vslam_ || steps_since_relocalise_ < kRelocaliseEvery) return;
	const std::string why = lostReason();
	if (why.empty()) return;
	steps_since_relocalise_ = 0;
	++lost_events;
	timeline_.note("lost: " + why + "; searching for the known features");
	if (why.rfind("only", 0) == 0 || failed_relocalisations_ > 0)
		filter_.inflateVehicleCovariance(kDoubt *
		                                 std::pow(4.0, std::min(failed_relocalisations_, kMaxDoubts)));
	const double grab0 = grab_seconds_();
	const auto t0 = std::chrono::steady_clock::now();
	const auto records = vslam_->relocalise(*images_head_, kRelocaliseFeatures, kRelocaliseRange_m);
	const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	timeline_.addRender(grab_seconds_() - grab0);
	timeline_.addCompute(std::max(0.0, wall - (grab_seconds_() - grab0)));
	std::string found;
	for (const auto& r : records)
	{
		timeline_.advance(o_.navigation.measurement_time_s);
		++image_cycles;
		if (r.nis) noteNis(r.label, *r.nis, r.accepted);
		if (r.accepted) found += (found.empty() ? "" : ", ") + r.label;
	}
	recent_.clear();
	if (found.empty())
	{
		++failed_relocalisations_;
		timeline_.note("not found again yet (" + std::to_string(records.size()) +
		               " known features sought)");
	}
	else
	{
		++recoveries, failed_relocalisations_ = 0;
		timeline_.note("found again via " + found);
	}
}

}  // namespace mrolr::mission
