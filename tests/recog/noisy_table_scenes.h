#pragma once
/** Noisy, fragmented table scenes of the lab objects, shared by the clique matcher's tests. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace mrolr::recog::test
{
using TableSceneFn =
    std::function<void(const std::string&, const ModelTable&, const std::vector<Feature>&)>;

/** Calls @p fn(name, model table, scene) for each lab object index of @p objects_k: the object
 * with two more lab objects on a table, seed @p seed + k, endpoints σ 0.7 mm, 40 % of the segments
 * fragmented and 10 % missing; the table of the default recognition options. */
inline void forNoisyTableScenes(std::initializer_list<size_t> objects_k, int seed,
                                const TableSceneFn& fn)
{
	const auto objects = sim::makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	sim::SceneNoise noise;
	noise.endpoint_sigma_mm = 0.7, noise.fragment_probability = 0.4, noise.missing_fraction = 0.1;
	for (const size_t k : objects_k)
	{
		const ModelTable table(objects[k], opts.auto_clique_count, opts.auto_clique_size,
		                       opts.auto_cliques, opts.file_cliques);
		const int kk = static_cast<int>(k);
		fn(objects[k].name, table,
		   featuresOf(sim::makeTableScene(objects, kk, 3, noise, seed + kk).scene));
	}
}
}  // namespace mrolr::recog::test
