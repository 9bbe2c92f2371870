#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/ObjectVisual.h>
#include <mrolr/sim/SimTurntable.h>
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CCylinder.h>

#include <ostream>

namespace mrolr::sim
{
namespace
{
using O = SimTurntableOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& simTurntableOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("step_deg", &O::step_deg, 1, 180, kOpt)
	    .number("axis_distance_m", &O::axis_distance_m, 0.2, 5, kOpt)
	    .number("top_below_c0_m", &O::top_below_c0_m, -10, 10, kOpt)
	    .number("disc_radius_m", &O::disc_radius_m, 0.01, 1, kOpt)
	    .number("disc_grey", &O::disc_grey, 0, 1, kOpt)
	    .number("backdrop_grey", &O::backdrop_grey, 0, 1, kOpt)
	    .number("backdrop_behind_m", &O::backdrop_behind_m, 0.05, 10, kOpt);
	return b;
}
}  // namespace

void SimTurntableOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                             const std::string& section)
{
	simTurntableOptionsBinder().load(cfg, section, *this);
}

void SimTurntableOptions::dump(std::ostream& out) const
{
	simTurntableOptionsBinder().dump(out, *this);
}

SimTurntable::SimTurntable(StereoRenderer& renderer, const world::ObjectShape& shape,
                           const SimTurntableOptions& options)
    : renderer_(renderer), options_(options), scene_(mrpt::opengl::COpenGLScene::Create())
{
	const double r = options.disc_radius_m;
	auto disc = mrpt::opengl::CCylinder::Create(float(r), float(r), 0.02f, 64);
	disc->setPose(geometry::cameraPoseToMrpt(T_TinC0() * Eigen::Translation3d(0, 0, -0.02)));
	const float g = float(options.disc_grey);
	disc->setColor(g, g, g);
	scene_->insert(disc);
	if (options.backdrop_grey > 0) scene_->insert(backdrop());
	object_ = objectVisual(shape);
	scene_->insert(object_);
	const Eigen::Vector3d mid = T_TinC0() * Eigen::Vector3d(0, 0, shape.heightMm() * 5e-4);
	angles_ = renderer_.head().fixate(mid);
	placeObject();
}

mrpt::opengl::CBox::Ptr SimTurntable::backdrop() const
{
	// a 3 m wide, 2 m high screen standing behind the axis, facing the head (C0 axes: z forward)
	const double z = options_.axis_distance_m + options_.backdrop_behind_m;
	auto b = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(z, -1.5, -1.0),
	                                    mrpt::math::TPoint3D(z + 0.01, 1.5, 1.0));
	const float g = float(options_.backdrop_grey);
	b->setColor(g, g, g);
	return b;
}

Eigen::Isometry3d SimTurntable::T_TinC0() const
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = geometry::R_mrptFromThesis().transpose();  // T's (x, y, z) = C0's (z, x, y)
	T.translation() = Eigen::Vector3d(0, -options_.top_below_c0_m, options_.axis_distance_m);
	return T;
}

Eigen::Isometry3d SimTurntable::T_TinL() const
{
	return renderer_.head().T_LinC0(angles_).inverse() * T_TinC0();
}

Eigen::Isometry3d SimTurntable::T_OinL() const
{
	return T_TinL() * Eigen::AngleAxisd(angle_deg_ * M_PI / 180, Eigen::Vector3d::UnitZ());
}

void SimTurntable::placeObject()
{
	const Eigen::Isometry3d T_OinC0 =
	    T_TinC0() * Eigen::AngleAxisd(angle_deg_ * M_PI / 180, Eigen::Vector3d::UnitZ());
	object_->setPose(geometry::cameraPoseToMrpt(T_OinC0));
}

void SimTurntable::rotateBy(double step_deg)
{
	angle_deg_ += step_deg;
	placeObject();
}

hw::StereoImages SimTurntable::grab()
{
	const auto f = renderer_.render(*scene_, Eigen::Isometry3d::Identity(), angles_, frames_++);
	return hw::StereoImages{f.left, f.right, angles_, 0};
}

}  // namespace mrolr::sim
