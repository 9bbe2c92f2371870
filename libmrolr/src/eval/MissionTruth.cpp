// The world's truth after a run: from the lab, to and from T.json.
#include <mrolr/eval/MissionTruth.h>
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/sim/ObjectWireFrame.h>

#include <algorithm>
#include <cmath>

namespace mrolr::eval
{
namespace
{
using nlohmann::json;

const json& field(const json& j, const char* key, const std::string& source)
{
	if (!j.is_object() || !j.contains(key))
		throw std::runtime_error(source + ": missing field '" + key + "'");
	return j.at(key);
}

double number(const json& j, const char* key, const std::string& source)
{
	const json& v = field(j, key, source);
	if (!v.is_number()) throw std::runtime_error(source + ": field '" + key + "' is not a number");
	return v.get<double>();
}

Eigen::Isometry3d transform(const json& j, const char* key, const std::string& source)
{
	try
	{
		return mission::isometryFrom(field(j, key, source));
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(source + ": field '" + key + "': " + e.what());
	}
}
/** An object's symmetry_deg: a non-empty list of numbers. */
std::vector<double> anglesOf(const json& j, const std::string& source)
{
	const bool ok = j.is_array() && !j.empty() &&
	                std::all_of(j.begin(), j.end(), [](const json& a) { return a.is_number(); });
	if (!ok) throw std::runtime_error(source + ": field 'symmetry_deg' is not a list of angles");
	return j.get<std::vector<double>>();
}

sim::GripperEvent::Kind kindNamed(const std::string& name, const std::string& source)
{
	using K = sim::GripperEvent::Kind;
	for (K k : {K::Held, K::Slipped, K::Pushed, K::KnockedOver, K::Table, K::Released})
		if (name == sim::GripperEvent::name(k)) return k;
	throw std::runtime_error(source + ": unknown gripper event kind '" + name + "'");
}

std::vector<sim::GripperEvent> gripperEventsFrom(const json& j, const std::string& source)
{
	if (!j.is_array()) throw std::runtime_error(source + ": 'gripper_events' is not a list");
	std::vector<sim::GripperEvent> out;
	for (const auto& e : j)
		out.push_back({kindNamed(field(e, "kind", source).get<std::string>(), source),
		               field(e, "object", source).get<std::string>(),
		               field(e, "detail", source).get<std::string>()});
	return out;
}
}  // namespace

json gripperEventsJson(const std::vector<sim::GripperEvent>& events)
{
	json out = json::array();
	for (const auto& e : events)
		out.push_back({{"kind", sim::GripperEvent::name(e.kind)}, {"object", e.object}, {"detail", e.detail}});
	return out;
}

MissionTruth truthOf(const sim::Lab& lab)
{
	MissionTruth t;
	t.final_zxphi = lab.truePose();
	const auto start = sim::placedObjectPoses(lab.options().world);
	for (const auto& [name, T] : lab.objectPoses())
	{
		t.objects.push_back({name, lab.modelOf(name), start.at(name), T});
		const auto shape = lab.shapes().find(t.objects.back().model);
		if (shape != lab.shapes().end())
			t.objects.back().symmetry_deg = symmetryAnglesDeg(sim::objectWireFrame(shape->second));
	}
	t.held = lab.held();
	t.on_board.assign(lab.onBoard().begin(), lab.onBoard().end());
	t.gripper_events = lab.gripperEvents();
	if (const auto& c = lab.simBase().lastContact()) t.contact = ContactTruth{c->what, c->p_zx_m};
	t.steps = lab.truth().steps;
	t.frames = lab.truth().frames;
	t.world = std::make_shared<world::World>(lab.options().world);
	t.T_C0inA_mm = lab.trueMount();  // the nominal mount off by the dock's error
	return t;
}

namespace
{
/** Every camera frame's truth: where C0 was and where each object was. */
json framesJson(const std::vector<sim::TruthLog::Frame>& frames)
{
	json out = json::array();
	for (const auto& f : frames)
	{
		json objects = json::object();
		for (const auto& [name, T] : f.T_OinW) objects[name] = mission::matrix34(T);
		out.push_back({{"frame", f.frame}, {"T_C0inW", mission::matrix34(f.T_C0inW)}, {"objects", objects}});
	}
	return out;
}

std::vector<sim::TruthLog::Frame> framesFrom(const json& j, const std::string& source)
{
	if (!j.is_array()) throw std::runtime_error(source + ": 'frames' is not a list");
	std::vector<sim::TruthLog::Frame> out;
	for (const auto& f : j)
	{
		sim::TruthLog::Frame fr;
		fr.frame = field(f, "frame", source).get<uint64_t>();
		fr.T_C0inW = transform(f, "T_C0inW", source);
		for (const auto& [name, T] : field(f, "objects", source).items())
			fr.T_OinW[name] = mission::isometryFrom(T);
		out.push_back(fr);
	}
	return out;
}
}  // namespace

json truthJson(const MissionTruth& t)
{
	json objects = json::array();
	for (const auto& o : t.objects)
		objects.push_back({{"name", o.name},
		                   {"model", o.model},
		                   {"T_OinW", mission::matrix34(o.T_OinW)},
		                   {"T_OinW_start", mission::matrix34(o.T_OinW_start)},
		                   {"symmetry_deg", o.symmetry_deg}});
	json contact = nullptr;
	if (t.contact)
		contact = {{"what", t.contact->what}, {"z_m", t.contact->p_zx.x()}, {"x_m", t.contact->p_zx.y()}};
	return {{"vehicle",
	         {{"z_m", t.final_zxphi.x()},
	          {"x_m", t.final_zxphi.y()},
	          {"phi_deg", t.final_zxphi.z() * 180.0 / M_PI}}},
	        {"objects", objects},
	        {"held", t.held.empty() ? json(nullptr) : json(t.held)},
	        {"on_board", t.on_board},
	        {"contact", contact},
	        {"gripper_events", gripperEventsJson(t.gripper_events)},
	        {"T_C0inA_mm", t.T_C0inA_mm ? mission::matrix34(*t.T_C0inA_mm) : json(nullptr)},
	        {"frames", framesJson(t.frames)}};
}

MissionTruth truthFromJson(const json& j, const std::string& source)
{
	MissionTruth t;
	const json& v = field(j, "vehicle", source);
	t.final_zxphi = {number(v, "z_m", source), number(v, "x_m", source),
	                 number(v, "phi_deg", source) * M_PI / 180.0};
	const json& objects = field(j, "objects", source);
	if (!objects.is_array()) throw std::runtime_error(source + ": 'objects' is not a list");
	for (const auto& o : objects)
	{
		ObjectTruth ot;
		ot.name = field(o, "name", source).get<std::string>();
		ot.model = o.contains("model") ? o.at("model").get<std::string>() : "";
		ot.T_OinW = transform(o, "T_OinW", source);
		ot.T_OinW_start = o.contains("T_OinW_start") ? transform(o, "T_OinW_start", source) : ot.T_OinW;
		if (o.contains("symmetry_deg")) ot.symmetry_deg = anglesOf(o.at("symmetry_deg"), source);
		t.objects.push_back(ot);
	}
	const json& held = field(j, "held", source);
	t.held = held.is_null() ? "" : held.get<std::string>();
	if (j.contains("on_board"))
	{
		if (!j.at("on_board").is_array()) throw std::runtime_error(source + ": 'on_board' is not a list");
		for (const auto& n : j.at("on_board"))
		{
			if (!n.is_string()) throw std::runtime_error(source + ": 'on_board' holds a non-name");
			t.on_board.push_back(n.get<std::string>());
		}
	}
	if (j.contains("contact") && !j.at("contact").is_null())
	{
		const json& c = j.at("contact");
		t.contact = ContactTruth{field(c, "what", source).get<std::string>(),
		                         {number(c, "z_m", source), number(c, "x_m", source)}};
	}
	if (j.contains("gripper_events")) t.gripper_events = gripperEventsFrom(j.at("gripper_events"), source);
	if (j.contains("T_C0inA_mm") && !j.at("T_C0inA_mm").is_null())
		t.T_C0inA_mm = transform(j, "T_C0inA_mm", source);
	if (j.contains("frames")) t.frames = framesFrom(j.at("frames"), source);
	return t;
}

}  // namespace mrolr::eval
