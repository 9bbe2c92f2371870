// The simulator's shortcut sensors: ideal landmark angles and exact scene wire-frames.
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/SimulatedSensors.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/util/OptionsBinder.h>

#include <cmath>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
class IdealLandmarks : public hw::LandmarkSensor
{
 public:
	IdealLandmarks(const Lab& lab, const IdealLandmarkOptions& o)
	    : lab_(lab), o_(o), rng_(lab.options().seed * 7919u + 101u)
	{
	}
	std::vector<Sighting> visible() override
	{
		std::vector<Sighting> out;
		for (const auto& l : lab_.options().world.landmarks)
			if (auto h = measure(l.name)) out.push_back({l.name, *h});
		return out;
	}
	std::optional<Eigen::Vector3d> measure(const std::string& name) override;

 private:
	const world::Patch* patchOf(const std::string& name) const
	{
		for (const auto& p : lab_.options().world.patches)
			if (p.name == name) return &p;
		return nullptr;
	}
	const Lab& lab_;
	IdealLandmarkOptions o_;
	std::mt19937 rng_;
};

std::optional<Eigen::Vector3d> IdealLandmarks::measure(const std::string& name)
{
	const auto* l = lab_.options().world.findLandmark(name);
	if (!l) return std::nullopt;
	const Eigen::Isometry3d T_C0inW = lab_.trueC0();
	const Eigen::Vector3d p_C0 = T_C0inW.inverse() * l->p_LinW;
	if (p_C0.norm() > o_.max_range_m || std::hypot(p_C0.x(), p_C0.z()) < 1e-9) return std::nullopt;
	if (const auto* p = patchOf(name); p && p->normal.dot(T_C0inW.translation() - p->centre_m) <= 0)
		return std::nullopt;  // a patch is seen only from its front
	const auto& b = lab_.options().bisight;
	const Eigen::Vector3d h = geometry::idealHeadMeasure(p_C0, b.interocular_m);
	const double k = M_PI / 180;
	if (std::abs(h[0]) > b.pan_limit_deg * k || std::abs(h[1]) > b.tilt_limit_deg * k ||
	    h[2] > b.vergence_limit_deg * k)
		return std::nullopt;
	std::normal_distribution<double> n(0, 1);
	return Eigen::Vector3d(h[0] + o_.std_pan_rad * n(rng_), h[1] + o_.std_elevation_rad * n(rng_),
	                       h[2] + o_.std_vergence_rad * n(rng_));
}

class ExactScenes : public hw::SceneSensor
{
 public:
	ExactScenes(const Lab& lab, const ExactSceneOptions& o)
	    : lab_(lab), o_(o), head_(lab.options().bisight), rng_(lab.options().seed + 7u)
	{
		for (const auto& [model, shape] : lab.shapes()) exact_[model] = objectWireFrame(shape);
	}
	model::WireFrame scene(const geometry::HeadAngles& angles) override;

 private:
	bool originInLeftImage(const Eigen::Vector3d& p_C0, const geometry::HeadAngles& a) const;
	const Lab& lab_;
	ExactSceneOptions o_;
	geometry::BiSightHead head_;
	std::mt19937 rng_;
	std::map<std::string, model::WireFrame> exact_;
};

bool ExactScenes::originInLeftImage(const Eigen::Vector3d& p_C0,
                                    const geometry::HeadAngles& a) const
{
	try
	{
		const auto px = head_.project(p_C0, a);
		const auto& c = head_.camera();
		return px.uL >= 0 && px.vL >= 0 && px.uL < c.width_px && px.vL < c.height_px;
	}
	catch (const geometry::GeometryError&)
	{
		return false;
	}
}

model::WireFrame ExactScenes::scene(const geometry::HeadAngles& angles)
{
	sim::SceneNoise noise;
	noise.endpoint_sigma_mm = o_.endpoint_sigma_mm;
	noise.missing_fraction = o_.missing_fraction;
	noise.fragment_probability = o_.fragment_probability;
	noise.hide_back_side = o_.hide_back_side;
	const Eigen::Isometry3d T_C0inW = lab_.trueC0();
	const Eigen::Isometry3d T_WinL = (T_C0inW * head_.T_LinC0(angles)).inverse();
	model::WireFrame out;
	out.frame = model::WireFrameFrame::LeftCamera;
	for (const auto& [name, T_OinW] : lab_.objectPoses())
	{
		const Eigen::Isometry3d T_OinL = T_WinL * T_OinW;
		const Eigen::Vector3d p = T_OinL.translation();
		if (p.z() <= 0.05 || p.norm() > o_.max_object_range_m) continue;
		if (!originInLeftImage((T_C0inW.inverse() * T_OinW).translation(), angles)) continue;
		const auto moved =
		    sim::placeInScene(exact_.at(lab_.modelOf(name)), geometry::inMm(T_OinL));
		sim::appendWireFrame(out, sim::corruptScene(moved, noise, rng_));
	}
	return out;
}
}  // namespace

namespace
{
constexpr auto kOpt = util::Presence::Optional;  // test sensors: every key has a default

const util::OptionsBinder<IdealLandmarkOptions>& idealBinder()
{
	using I = IdealLandmarkOptions;
	static const auto b = util::OptionsBinder<I>()
	                          .number("std_pan_rad", &I::std_pan_rad, 0, 1, kOpt)
	                          .number("std_elevation_rad", &I::std_elevation_rad, 0, 1, kOpt)
	                          .number("std_vergence_rad", &I::std_vergence_rad, 0, 1, kOpt)
	                          .number("max_range_m", &I::max_range_m, 0.1, 100, kOpt);
	return b;
}

const util::OptionsBinder<ExactSceneOptions>& exactBinder()
{
	using E = ExactSceneOptions;
	static const auto b =
	    util::OptionsBinder<E>()
	        .number("endpoint_sigma_mm", &E::endpoint_sigma_mm, 0, 100, kOpt)
	        .number("missing_fraction", &E::missing_fraction, 0, 0.9, kOpt)
	        .number("fragment_probability", &E::fragment_probability, 0, 1, kOpt)
	        .flag("hide_back_side", &E::hide_back_side, kOpt)
	        .number("max_object_range_m", &E::max_object_range_m, 0, 1e6, kOpt);
	return b;
}
}  // namespace

void IdealLandmarkOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                              const std::string& s)
{
	idealBinder().load(c, s, *this);
}

void ExactSceneOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                           const std::string& s)
{
	exactBinder().load(c, s, *this);
}

std::unique_ptr<hw::LandmarkSensor> makeLandmarkSensor(const std::string& name, const Lab& lab,
                                                       const IdealLandmarkOptions& o)
{
	if (name == "ideal_sim") return std::make_unique<IdealLandmarks>(lab, o);
	throw std::invalid_argument("'" + name + "' is not a simulated landmark sensor (ideal_sim)");
}

std::unique_ptr<hw::SceneSensor> makeSceneSensor(const std::string& name, const Lab& lab,
                                                 const ExactSceneOptions& o)
{
	if (name == "exact_sim") return std::make_unique<ExactScenes>(lab, o);
	throw std::invalid_argument("'" + name + "' is not a simulated scene sensor (exact_sim)");
}

}  // namespace mrolr::sim
