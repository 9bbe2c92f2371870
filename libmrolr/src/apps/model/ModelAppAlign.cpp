#include <mrolr/apps/ModelApp.h>
#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/JsonOptional.h>

#include <mrpt/config/CConfigFile.h>

#include <optional>

namespace mrolr::apps
{
namespace
{
nlohmann::json registrationJson(const ViewRegistration& r)
{
	nlohmann::json j = {{"view", r.view},
	                    {"known_angle_deg", r.known_angle_deg},
	                    {"registered", r.registered},
	                    {"features", r.features}};
	if (!r.registered) return j["reason"] = r.reason, j;
	j["pass"] = r.pass, j["score"] = r.score, j["level"] = r.level, j["seed"] = r.pass == 0;
	j["turn_deg"] = r.turn_deg, j["rot_err_deg"] = r.rot_err_deg;
	j["trans_err_mm"] = r.trans_err_mm, j["symmetry_deg"] = r.symmetry_deg;
	return j;
}
}  // namespace

model::WireFrame ModelApp::buildByRecognition(const model::TurntableSet& set,
                                              const stereo::SceneOptions& so,
                                              const model::TurntableOptions& to,
                                              const std::string& truth_wf)
{
	AlignOptions ao;
	ao.loadFromConfigFile(mrpt::config::CConfigFile(util::requireProjectFile(config_path)),
	                      "align");
	std::optional<model::WireFrame> truth;
	if (!truth_wf.empty()) truth = model::loadWireFrame(truth_wf);
	const AlignmentResult r = apps::buildByRecognition(set, so, to, ao, truth ? &*truth : nullptr);
	report["registration"] = nlohmann::json::array();
	for (const auto& v : r.views) report["registration"].push_back(registrationJson(v));
	report["views_registered"] = r.registered;
	return r.model;
}

}  // namespace mrolr::apps
