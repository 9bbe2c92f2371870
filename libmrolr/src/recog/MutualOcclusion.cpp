#include <mrolr/recog/MutualOcclusion.h>

#include <stdexcept>

namespace mrolr::recog
{
std::vector<Occluder> occludersOf(const std::vector<const Recognizer*>& recs,
                                  const std::vector<RecognitionResult>& results, size_t skip,
                                  double spacing_mm)
{
	if (recs.size() != results.size())
		throw std::invalid_argument("occludersOf: " + std::to_string(recs.size()) +
		                            " recognisers but " + std::to_string(results.size()) +
		                            " results");
	std::vector<Occluder> out;
	for (size_t i = 0; i < recs.size(); ++i)
	{
		if (i == skip || !results[i].found) continue;
		out.push_back(
		    {recs[i]->edgeSamples(spacing_mm), &recs[i]->selfOcclusion(), results[i].T_OinS});
	}
	return out;
}

}  // namespace mrolr::recog
