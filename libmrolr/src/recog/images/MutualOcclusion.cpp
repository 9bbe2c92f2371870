#include <mrolr/recog/images/MutualOcclusion.h>

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

Eigen::Vector3d centroidOf(const std::vector<EdgeSample>& samples_O)
{
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	for (const auto& s : samples_O) sum += s.p_O;
	return samples_O.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(samples_O.size()));
}

bool interpenetrates(const Recognizer& rec, const Eigen::Isometry3d& T_OinL,
                     const std::vector<Occluder>& occluders)
{
	const Eigen::Vector3d c_L = T_OinL * centroidOf(rec.edgeSamples(3.0));
	for (const auto& o : occluders)
	{
		if (o.occ && o.occ->contains(o.T_OinL.inverse() * c_L)) return true;
		const Eigen::Vector3d oc_L = o.T_OinL * centroidOf(o.samples_O);
		if (rec.selfOcclusion().contains(T_OinL.inverse() * oc_L)) return true;
	}
	return false;
}

std::vector<RecognitionResult> searchBehindFound(const std::vector<const Recognizer*>& recs,
                                                 const std::vector<RecognitionResult>& first,
                                                 const ImageVerifier& images, double spacing_mm,
                                                 const SearchBehind& search)
{
	std::vector<RecognitionResult> out = first;
	for (size_t i = 0; i < recs.size(); ++i)
	{
		if (first[i].found) continue;
		const auto occluders = occludersOf(recs, first, i, spacing_mm);
		if (occluders.empty()) continue;
		RecognitionResult r = search(i, images.withOccluders(occluders));
		r.ms += first[i].ms;
		r.times += first[i].times;
		if (!r.found || interpenetrates(*recs[i], r.T_OinS, occluders))
		{
			out[i].ms = r.ms;  // the second search's time counts
			out[i].times = r.times;
			continue;
		}
		r.occluders = static_cast<int>(occluders.size());
		out[i] = r;
	}
	return out;
}

}  // namespace mrolr::recog
