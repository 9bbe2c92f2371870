#include <mrolr/vision/SyntheticWorld.h>

namespace mrolr::vision
{
SyntheticWorld::SyntheticWorld(const geometry::BiSightHead& head,
                               std::vector<TexturedLandmark> landmarks, double noise_sigma,
                               std::uint64_t seed)
    : landmarks_(std::move(landmarks)), head_device_(head, noise_sigma, seed)
{
	constants_.interocular_m = head.options().interocular_m;
	constants_.head_height_m = head.options().head_height_m;
	setVehicle(Eigen::Vector3d::Zero());
}

void SyntheticWorld::setVehicle(const Eigen::Vector3d& x_true)
{
	x_true_ = x_true;
	std::vector<TexturedPoint> pts;
	pts.reserve(landmarks_.size());
	for (const auto& l : landmarks_)
		pts.push_back({slam::pointInHead(x_true, l.p_inW, constants_), l.texture});
	head_device_.setPoints(std::move(pts));
}

}  // namespace mrolr::vision
