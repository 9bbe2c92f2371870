// Recognizer's edge samples for image verification, with their sight against the model's
// self-occlusion: built once per spacing, then shared by every pose the images score.
#include <mrolr/recog/Recognizer.h>

#include <map>
#include <mutex>

namespace mrolr::recog
{
struct Recognizer::SampleCache
{
	std::mutex mutex;
	std::map<double, std::unique_ptr<const SightedSamples>> by_spacing_mm;
};

std::shared_ptr<Recognizer::SampleCache> Recognizer::newSampleCache()
{
	return std::make_shared<SampleCache>();
}

const SightedSamples& Recognizer::sightedSamples(double spacing_mm) const
{
	std::lock_guard<std::mutex> lock(samples_->mutex);
	auto& slot = samples_->by_spacing_mm[spacing_mm];
	if (!slot)
		slot = std::make_unique<const SightedSamples>(edgeSamples(spacing_mm), occlusion_.get());
	return *slot;
}

}  // namespace mrolr::recog
