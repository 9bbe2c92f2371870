// The whole set: the shipped generator, the models searched, every model in every scene.
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/recog/images/MutualOcclusion.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/util/Cli.h>

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace mrolr::eval
{
namespace
{
namespace fs = std::filesystem;

/** The recognisers of the models and the symmetries of their objects, in model order. */
struct Searchers
{
	std::vector<recog::Recognizer> recs;
	std::vector<std::vector<double>> symmetries;
};

Searchers searchersOf(const EvalSceneGenerator& gen, const std::vector<model::WireFrame>& models,
                      const recog::RecognitionOptions& options)
{
	Searchers s;
	for (const auto& m : models)
	{
		s.recs.emplace_back(m, options);
		s.symmetries.push_back(symmetryAnglesDeg(gen.truthWireFrame(m.name)));
	}
	return s;
}

std::vector<std::string> datasetModelPaths()
{
	std::vector<std::string> out;
	for (const auto& e : fs::directory_iterator(util::requireProjectFile("datasets/objects")))
		if (e.path().extension() == ".wf") out.push_back(e.path().string());
	std::sort(out.begin(), out.end());
	return out;
}

/** Mutual occlusion (recog::searchBehindFound): each model of @p cases (one per searcher, scene
 * @p s) not found is searched again with the found ones as occluders; a find replaces its case and
 * its entry of @p found. */
void searchBehindFound(const Searchers& sr, const EvalScene& s, const recog::ImageVerifier& images,
                       const EvaluationOptions& opts, std::vector<EvalCase>::iterator cases,
                       std::vector<recog::RecognitionResult>& found)
{
	std::vector<const recog::Recognizer*> ptrs;
	for (const auto& r : sr.recs) ptrs.push_back(&r);
	std::map<size_t, EvalCase> second;  // the cases of the second search, by model
	auto search = [&](size_t i, const recog::ImageVerifier& behind)
	{
		second[i] = evaluateCase(sr.recs[i], s, sr.symmetries[i], opts,
		                         {std::nullopt, std::cref(behind), s.plane_L, true});
		return second[i].result;
	};
	const auto after = recog::searchBehindFound(ptrs, found, images,
	                                            images.options().sample_spacing_mm, search);
	for (const auto& [i, c] : second)
	{
		EvalCase& before = cases[static_cast<std::ptrdiff_t>(i)];
		if (after[i].found) before = c;
		before.result = after[i];
		before.ms = after[i].ms;
		found[i] = after[i];
	}
}

/** Appends the cases of scene @p s to @p cases; returns what was found, one result a model. */
std::vector<recog::RecognitionResult> evaluateScene(const Searchers& sr, const EvalScene& s,
                                                    const SetSearchOptions& search,
                                                    const EvaluationOptions& opts,
                                                    std::vector<EvalCase>& cases)
{
	std::unique_ptr<recog::ImageVerifier> images;
	if (search.images)
		images = std::make_unique<recog::ImageVerifier>(s.left, s.right, s.calib, *search.images);
	std::vector<recog::RecognitionResult> found;
	const size_t first = cases.size();
	recog::SceneContext context;
	context.plane = s.plane_L;
	if (images) context.images = std::cref(*images);
	for (size_t i = 0; i < sr.recs.size(); ++i)
	{
		cases.push_back(evaluateCase(sr.recs[i], s, sr.symmetries[i], opts, context));
		found.push_back(cases.back().result);
	}
	if (images && search.images->mutual_occlusion)
		searchBehindFound(sr, s, *images, opts, cases.begin() + static_cast<std::ptrdiff_t>(first),
		                  found);
	return found;
}
}  // namespace

std::unique_ptr<EvalSceneGenerator> makeSceneGenerator(const EvaluationOptions& opts,
                                                       const std::string& scene_config)
{
	const auto lab = world::World::load(util::requireProjectFile(opts.world));
	sim::RenderOptions ro;
	ro.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile("config/sim.ini")),
	                      "render");
	stereo::SceneOptions so;
	so.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile(scene_config)),
	                      "scene");
	const geometry::BiSightHead head(
	    geometry::BiSightOptions::fromFile(util::requireProjectFile("config/bisight.ini")));
	return std::make_unique<EvalSceneGenerator>(opts, head, ro, so, sim::loadObjectShapes(lab));
}

std::vector<model::WireFrame> truthModels(const EvalSceneGenerator& gen)
{
	std::vector<model::WireFrame> out;
	for (const auto& [name, shape] : gen.shapes()) out.push_back(gen.truthWireFrame(name));
	return out;
}

std::vector<model::WireFrame> databaseModels(const EvalSceneGenerator& gen,
                                             const std::vector<std::string>& paths)
{
	std::vector<model::WireFrame> out;
	for (const auto& p : paths.empty() ? datasetModelPaths() : paths)
		out.push_back(model::loadWireFrame(p));
	for (const auto& m : out) gen.truthWireFrame(m.name);  // throws for a model of no object
	return out;
}

std::vector<EvalCase> evaluateSet(EvalSceneGenerator& gen,
                                  const std::vector<model::WireFrame>& models,
                                  const SetSearchOptions& search, const SceneObserver& observe)
{
	const Searchers sr = searchersOf(gen, models, search.recognition);
	std::vector<EvalCase> cases;
	for (int k = 0; k < gen.options().scenes; ++k)
	{
		const EvalScene s = gen.make(k);
		const auto found = evaluateScene(sr, s, search, gen.options(), cases);
		if (observe) observe(s, found);
	}
	return cases;
}

}  // namespace mrolr::eval
