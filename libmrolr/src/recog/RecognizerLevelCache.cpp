// Recognizer's memory of the last scene it searched: the clusters and 3D-verified poses of each
// level, which depend on the scene, its up direction and whether images judge them, not on the
// images themselves. A second search of the same scene behind the objects found in it
// (MutualOcclusion.h; SceneContext::repeat) takes them from here instead of matching the cliques
// again.
#include <mrolr/recog/Recognizer.h>

#include <algorithm>
#include <map>
#include <mutex>

namespace mrolr::recog
{
namespace
{
bool sameFeature(const Feature& a, const Feature& b)
{
	return a.kind == b.kind && a.id == b.id && a.u == b.u && a.m == b.m && a.p1 == b.p1 &&
	       a.p2 == b.p2 && a.len_mm == b.len_mm && a.a_mm == b.a_mm && a.b_mm == b.b_mm;
}

bool sameScene(const std::vector<Feature>& a, const std::vector<Feature>& b)
{
	return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameFeature);
}
}  // namespace

struct Recognizer::LevelCache
{
	std::mutex mutex;
	std::vector<Feature> scene;
	std::optional<Eigen::Vector3d> up_S;
	bool images = false;
	std::map<size_t, LevelHypotheses> by_level;

	/** True when the cache holds @p scene seen as given; otherwise it is emptied for it (and
	 * false). */
	bool holds(const std::vector<Feature>& s, const Eigen::Vector3d* up, bool with_images)
	{
		const bool same_up = up ? up_S && *up_S == *up : !up_S;
		if (same_up && images == with_images && sameScene(scene, s)) return true;
		scene = s, images = with_images, by_level.clear();
		up_S = up ? std::optional<Eigen::Vector3d>(*up) : std::nullopt;
		return false;
	}
};

std::shared_ptr<Recognizer::LevelCache> Recognizer::newLevelCache()
{
	return std::make_shared<LevelCache>();
}

Recognizer::LevelHypotheses Recognizer::levelHypotheses(const std::vector<Feature>& scene,
                                                        const OrientedScene& os, size_t level,
                                                        FocusBounds& bounds,
                                                        const Eigen::Vector3d* up_S,
                                                        const ImageVerifier* images,
                                                        bool repeat, RecognitionTimes& times) const
{
	if (repeat)
	{
		std::lock_guard<std::mutex> lock(levels_cache_->mutex);
		if (levels_cache_->holds(scene, up_S, images != nullptr))
		{
			const auto it = levels_cache_->by_level.find(level);
			if (it != levels_cache_->by_level.end()) return it->second;
		}
	}
	LevelHypotheses h = computeLevelHypotheses(scene, os, level, bounds, up_S, images, times);
	std::lock_guard<std::mutex> lock(levels_cache_->mutex);
	levels_cache_->holds(scene, up_S, images != nullptr);  // emptied unless it holds this scene
	levels_cache_->by_level[level] = h;
	return h;
}

}  // namespace mrolr::recog
