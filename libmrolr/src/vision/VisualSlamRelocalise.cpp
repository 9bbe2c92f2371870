// Finding the map again after losing it: the known features, nearest first, sought in the wide
// ellipses of a doubtful estimate and accepted only as a jointly compatible set.
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>
#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/vision/VisualSlam.h>

#include <algorithm>

namespace mrolr::vision
{
std::vector<CycleRecord> VisualSlam::relocalise(StereoHeadDevice& device, int count,
                                                double max_range_m)
{
	const Eigen::Vector3d xv = filter_.vehicle();
	const Eigen::Vector3d c0 = slam::headCentreInW(xv, filter_.options().head.constants);
	std::vector<std::pair<double, size_t>> known;
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
	{
		const double d = (filter_.feature(i) - c0).norm();
		// the view rules of 5.2.1 assume a trusted estimate: only the head's reach counts here
		if (filter_.info(i).known && d <= max_range_m &&
		    slam::headCanFixate(xv, filter_.feature(i), filter_.options().head) ==
		        slam::Visibility::Visible)
			known.emplace_back(d, i);
	}
	std::sort(known.begin(), known.end());
	std::vector<CycleRecord> out;
	for (const auto& [d, i] : known)
	{
		if (static_cast<int>(out.size()) >= count) break;
		CycleRecord r;
		r.measured = true, r.feature = i, r.label = filter_.info(i).label;
		r.vs = slam::innovationVolume(filter_.innovationCovariance(i),
		                              filter_.options().innovation_volume_sigma);
		noteSaccade(r);
		matchSelected(device, r);
		out.push_back(std::move(r));
	}
	if (!out.empty()) applyJointly(out);
	return out;
}

}  // namespace mrolr::vision
