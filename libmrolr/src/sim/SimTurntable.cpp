#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/ObjectVisual.h>
#include <mrolr/sim/SimTurntable.h>
#include <mrolr/util/Config.h>

#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CCylinder.h>

#include <ostream>

namespace mrolr::sim
{
void SimTurntableOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                             const std::string& section)
{
	using namespace util;
	step_deg = readDouble(cfg, section, "step_deg", step_deg);
	axis_distance_m = readDouble(cfg, section, "axis_distance_m", axis_distance_m);
	top_below_c0_m = readDouble(cfg, section, "top_below_c0_m", top_below_c0_m);
	disc_radius_m = readDouble(cfg, section, "disc_radius_m", disc_radius_m);
	disc_grey = readDouble(cfg, section, "disc_grey", disc_grey);
	backdrop_grey = readDouble(cfg, section, "backdrop_grey", backdrop_grey);
	backdrop_behind_m = readDouble(cfg, section, "backdrop_behind_m", backdrop_behind_m);
	requireInRange(cfg, section, "disc_grey", disc_grey, 0, 1);
	requireInRange(cfg, section, "backdrop_grey", backdrop_grey, 0, 1);
	requireInRange(cfg, section, "backdrop_behind_m", backdrop_behind_m, 0.05, 10);
	requireInRange(cfg, section, "step_deg", step_deg, 1, 180);
	requireInRange(cfg, section, "axis_distance_m", axis_distance_m, 0.2, 5);
	requireInRange(cfg, section, "disc_radius_m", disc_radius_m, 0.01, 1);
}

void SimTurntableOptions::dump(std::ostream& out) const
{
	out << "step_deg = " << step_deg << "\naxis_distance_m = " << axis_distance_m
	    << "\ntop_below_c0_m = " << top_below_c0_m << "\ndisc_radius_m = " << disc_radius_m
	    << "\ndisc_grey = " << disc_grey << "\nbackdrop_grey = " << backdrop_grey
	    << "\nbackdrop_behind_m = " << backdrop_behind_m << "\n";
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
