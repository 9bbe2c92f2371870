// The gripper against the world's objects and tables: pushes, falls, a grip that must fit.
#include <mrolr/sim/GripperPhysics.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
const Eigen::Vector3d kUp_W = Eigen::Vector3d::UnitY();

/** True when @p p_W lies over (or under) table @p t's top rectangle. */
bool overTable(const world::Table& t, const Eigen::Vector3d& p_W)
{
	const double yaw = t.yaw_deg * M_PI / 180.0;
	const double dz = p_W.z() - t.z_m, dx = p_W.x() - t.x_m;
	const double along_z = dz * std::cos(yaw) + dx * std::sin(yaw);
	const double along_x = -dz * std::sin(yaw) + dx * std::cos(yaw);
	return std::abs(along_z) <= t.depth_m / 2 && std::abs(along_x) <= t.length_m / 2;
}

std::string mm(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.1f mm", v);
	return buf;
}

/** The horizontal part of @p v. */
Eigen::Vector3d horizontal(Eigen::Vector3d v)
{
	v.y() = 0;
	return v;
}
}  // namespace

const char* GripperEvent::name(Kind k)
{
	switch (k)
	{
		case Kind::Held: return "held";
		case Kind::Slipped: return "slipped";
		case Kind::Pushed: return "pushed";
		case Kind::KnockedOver: return "knocked_over";
		case Kind::Table: return "table";
		case Kind::Released: return "released";
	}
	return "?";
}

namespace
{
using O = GripperPhysicsOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& gripperPhysicsOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("compliance_mm", &O::compliance_mm, 0, 20, kOpt)
	    .number("finger_thickness_mm", &O::finger_thickness_mm, 1, 50, kOpt)
	    .number("sample_step_mm", &O::sample_step_mm, 0.5, 20, kOpt)
	    .number("motion_step_mm", &O::motion_step_mm, 0.5, 50, kOpt)
	    .number("knock_over_height_fraction", &O::knock_over_height_fraction, 0, 1, kOpt)
	    .number("knock_over_aspect", &O::knock_over_aspect, 0, 10, kOpt);
	return b;
}
}  // namespace

void GripperPhysicsOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                               const std::string& section)
{
	gripperPhysicsOptionsBinder().load(cfg, section, *this);
}

void GripperPhysicsOptions::dump(std::ostream& out) const
{
	gripperPhysicsOptionsBinder().dump(out, *this);
}

std::vector<Eigen::Vector3d> fingerPoints(const JawGeometry& jaws, double thickness_mm,
                                          double separation_mm, double step_mm)
{
	const auto count = [step_mm](double len) { return std::max(2, int(std::ceil(len / step_mm)) + 1); };
	const int nx = count(jaws.finger_width_mm), nz = count(jaws.finger_length_mm),
	          ny = count(thickness_mm);
	std::vector<Eigen::Vector3d> pts;
	pts.reserve(size_t(2 * nx * ny * nz));
	for (int side : {-1, 1})
		for (int ix = 0; ix < nx; ++ix)
			for (int iy = 0; iy < ny; ++iy)
				for (int iz = 0; iz < nz; ++iz)
					pts.emplace_back((ix / double(nx - 1) - 0.5) * jaws.finger_width_mm,
					                 side * (separation_mm / 2 + iy / double(ny - 1) * thickness_mm),
					                 (iz / double(nz - 1) - 0.5) * jaws.finger_length_mm);
	return pts;
}

double widthAcrossMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_OinG_mm,
                     const JawGeometry& jaws)
{
	// the jaws' slab (|x_G| within the fingers' width) at any z_G within 0.15 m; along y_G a
	// little beyond the open jaws (wider cannot be held)
	const SlabSampling s{jaws.finger_width_mm / 2, 5, jaws.opening_mm / 2 + 20, 150, 301};
	return extentAlongYMm(shape, T_OinG_mm.inverse(Eigen::Isometry), s);
}

GripperPhysics::GripperPhysics(const world::World& world,
                               const std::map<std::string, world::ObjectShape>& shapes,
                               std::map<std::string, std::string> model_of, const JawGeometry& jaws,
                               const GripperPhysicsOptions& o,
                               std::map<std::string, Eigen::Isometry3d>& objects)
    : world_(world), shapes_(shapes), model_of_(std::move(model_of)), jaws_(jaws), o_(o),
      objects_(objects)
{
}

const world::ObjectShape& GripperPhysics::shapeOf(const std::string& name) const
{
	const auto m = model_of_.find(name);
	const auto s = m == model_of_.end() ? shapes_.end() : shapes_.find(m->second);
	if (s == shapes_.end())
		throw std::logic_error("GripperPhysics: no shape for object '" + name + "'");
	return s->second;
}

std::vector<Eigen::Vector3d> GripperPhysics::inside(const std::string& name,
                                                    const Eigen::Isometry3d& T_GinW,
                                                    const std::vector<Eigen::Vector3d>& points_G) const
{
	const auto& shape = shapeOf(name);
	const Eigen::Isometry3d T_OinW = objects_.at(name);
	const double reach_m = 1e-3 * (shape.heightMm() + 2 * jaws_.opening_mm + jaws_.finger_length_mm);
	std::vector<Eigen::Vector3d> out;
	if ((T_OinW.translation() - T_GinW.translation()).norm() > reach_m + 0.3) return out;
	const Eigen::Isometry3d T_GinO_mm = geometry::inMm(T_OinW.inverse(Eigen::Isometry) * T_GinW);
	for (const auto& p_G : points_G)
		if (const Eigen::Vector3d p_O = T_GinO_mm * p_G; insideShape(shape, p_O))
			out.push_back(T_OinW * (p_O / 1000.0));
	return out;
}

std::optional<std::string> GripperPhysics::tableEntered(
    const Eigen::Isometry3d& T_GinW, const std::vector<Eigen::Vector3d>& points_G) const
{
	for (const auto& t : world_.tables)
	{
		const double top_y = world_.room.floorY() + t.top_height_m;
		for (const auto& p_G : points_G)
		{
			const Eigen::Vector3d p = T_GinW * (p_G / 1000.0);
			if (p.y() > top_y || p.y() < world_.room.floorY()) continue;
			if (overTable(t, p)) return t.name;
		}
	}
	return std::nullopt;
}

std::pair<double, std::string> GripperPhysics::supportUnder(const Eigen::Vector3d& p) const
{
	constexpr double kTouch_m = 0.002;  // resting on a top counts as above it
	std::pair<double, std::string> best{world_.room.floorY(), "the floor"};
	for (const auto& t : world_.tables)
	{
		const double top_y = world_.room.floorY() + t.top_height_m;
		if (top_y > p.y() + kTouch_m || top_y <= best.first) continue;
		if (overTable(t, p)) best = {top_y, "table '" + t.name + "'"};
	}
	return best;
}

bool GripperPhysics::release(const std::string& name, const DeckSupport& deck)
{
	auto& T = objects_.at(name);
	const Eigen::Vector3d p = T.translation();
	auto [support_y, what] = supportUnder(p);
	const Eigen::Vector3d on_deck = deck.T_TopInW.inverse() * p;
	const bool over_deck = std::abs(on_deck.x()) <= deck.half_x_m &&
	                       std::abs(on_deck.z()) <= deck.half_z_m && on_deck.y() >= -0.002;
	const double deck_y = deck.T_TopInW.translation().y();
	if (over_deck && deck_y > support_y) support_y = deck_y, what = "the robot's deck";
	const double drop_mm = 1000.0 * (p.y() - support_y);
	T.translation().y() = support_y;
	const double tilt_deg =
	    std::acos(std::clamp(T.linear().col(2).dot(kUp_W), -1.0, 1.0)) * 180.0 / M_PI;
	char buf[200];
	std::snprintf(buf, sizeof buf, "the jaws opened: %s came down %.0f mm onto %s", name.c_str(),
	              drop_mm, what.c_str());
	events_.push_back({GripperEvent::Kind::Released, name, buf});
	const auto [width_mm, height_mm] = widthAndHeight(shapeOf(name));
	const bool tall = height_mm > o_.knock_over_aspect * width_mm;
	if ((drop_mm > kGentleDrop_mm && tall) || tilt_deg > 20)
	{
		const Eigen::Vector3d d = T.linear().col(0);  // it tips over its own x side
		knockOver(name, d);
		events_.back().detail = name + " fell over after a drop of " +
		                        std::to_string(static_cast<int>(drop_mm)) + " mm onto " + what;
	}
	return what == "the robot's deck";
}

std::pair<double, double> GripperPhysics::widthAndHeight(const world::ObjectShape& shape) const
{
	double width = 0;
	for (const auto& p : shape.parts)
		if (p.kind == world::ShapePart::Kind::Box)
			width = std::max(width, std::min(p.size_mm.x(), p.size_mm.y()));
		else if (p.kind == world::ShapePart::Kind::Frustum)
			width = std::max(width, 2 * std::max(p.radius_bottom_mm, p.radius_top_mm));
	return {width, shape.heightMm()};
}

void GripperPhysics::push(const std::string& name, const Eigen::Vector3d& contact_W,
                          const Eigen::Vector3d& d_W)
{
	auto& T = objects_.at(name);
	Eigen::Vector3d d = horizontal(d_W);
	if (d.norm() < 1e-5)  // a vertical move: the finger shoves it away from the contact
		d = horizontal(T.translation() - contact_W).normalized() * d_W.norm();
	if (!d.allFinite()) return;
	T.translation() += d;
	if (!events_.empty() && events_.back().kind == GripperEvent::Kind::Pushed &&
	    events_.back().object == name)
		return;
	events_.push_back({GripperEvent::Kind::Pushed, name,
	                   "a finger met " + name + " during a move and pushed it"});
}

void GripperPhysics::knockOver(const std::string& name, const Eigen::Vector3d& d_W)
{
	auto& T = objects_.at(name);
	const Eigen::Vector3d dir = horizontal(d_W).normalized();
	if (!dir.allFinite()) return;
	const double half_width_m = widthAndHeight(shapeOf(name)).first / 2000.0;
	const Eigen::Vector3d pivot = T.translation() + half_width_m * dir;
	const Eigen::AngleAxisd tip(M_PI / 2, kUp_W.cross(dir));  // the top goes along dir
	T.linear() = tip * T.linear();
	T.translation() = pivot + tip * (T.translation() - pivot);
	fallen_[name] = true;
	events_.push_back({GripperEvent::Kind::KnockedOver, name,
	                   "a finger hit " + name + " high during a move: it fell over"});
}

std::optional<std::string> GripperPhysics::step(const Eigen::Isometry3d& T_GinW_before,
                                                const Eigen::Isometry3d& T_GinW,
                                                double separation_mm, const std::string& held)
{
	const auto pts = fingerPoints(jaws_, o_.finger_thickness_mm, separation_mm, o_.sample_step_mm);
	if (auto table = tableEntered(T_GinW, pts))
	{
		events_.push_back({GripperEvent::Kind::Table, "",
		                   "a finger met table '" + *table + "': the arm stopped"});
		return table;
	}
	const Eigen::Vector3d d_W = T_GinW.translation() - T_GinW_before.translation();
	for (const auto& entry : objects_)
	{
		const std::string& name = entry.first;
		if (name == held) continue;
		const auto in = inside(name, T_GinW, pts);
		if (in.empty()) continue;
		Eigen::Vector3d contact = Eigen::Vector3d::Zero();
		for (const auto& p : in) contact += p;
		contact /= double(in.size());
		const auto [width, height] = widthAndHeight(shapeOf(name));
		const double contact_height_mm = 1000.0 * (contact - entry.second.translation()).dot(
		                                              entry.second.linear().col(2));
		if (!fallen_[name] && height > o_.knock_over_aspect * width &&
		    contact_height_mm > o_.knock_over_height_fraction * height)
			knockOver(name, d_W);
		else
			push(name, contact, d_W);
	}
	return std::nullopt;
}

GripperPhysics::Grip GripperPhysics::close(const Eigen::Isometry3d& T_GinW)
{
	const auto open = fingerPoints(jaws_, o_.finger_thickness_mm, jaws_.opening_mm, o_.sample_step_mm);
	std::string best;
	double best_d = 1e9, best_width = 0;
	for (const auto& [name, T_OinW] : objects_)
	{
		const Eigen::Isometry3d T_OinG_mm =
		    geometry::inMm(T_GinW.inverse(Eigen::Isometry) * T_OinW);
		const double w = jawWidthMm(shapeOf(name), T_OinG_mm, jaws_);
		if (w <= 0 || !inside(name, T_GinW, open).empty()) continue;  // between the jaws, untouched
		if (const double d = T_OinG_mm.translation().norm(); d < best_d)
			best = name, best_d = d, best_width = w;
	}
	if (best.empty()) return {};
	Eigen::Isometry3d T_OinG = T_GinW.inverse(Eigen::Isometry) * objects_.at(best);
	const double across = widthAcrossMm(shapeOf(best), geometry::inMm(T_OinG), jaws_);
	if (best_width < across - o_.compliance_mm)
	{
		// the jaws close on a chord: the object is squeezed out along the approach axis
		const double z_mm = 1000.0 * T_OinG.translation().z();
		const double out_mm = jaws_.finger_length_mm / 2 + across / 2 - std::abs(z_mm);
		objects_.at(best).translation() +=
		    horizontal(T_GinW.linear().col(2) * (z_mm < 0 ? -1.0 : 1.0) * out_mm / 1000.0);
		events_.push_back({GripperEvent::Kind::Slipped, best,
		                   "the jaws closed on " + best + " " + mm(best_width) + " apart, short of its " +
		                       mm(across) + " width there: it slid out"});
		return {};
	}
	events_.push_back({GripperEvent::Kind::Held, best,
	                   "the jaws hold " + best + " " + mm(best_width) + " apart (its width there " +
	                       mm(across) + ")"});
	return {best, best_width, T_OinG};
}

}  // namespace mrolr::sim
