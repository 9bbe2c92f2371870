#pragma once
/** The simulated model-building turntable (thesis 6.1, appendix B.2.1): one object on a dark disc
 * that turns in fixed steps about its vertical axis before the head's two cameras, which stay fixed
 * and calibrated. The turntable frame T has its z axis on the rotation axis and its origin on the
 * disc's top; the object frame O coincides with T at angle 0 (thesis 6.1). */

#include <mrolr/hw/Devices.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/world/ObjectShape.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <iosfwd>

namespace mrolr::sim
{
/** Section [sim_turntable] of config/sim.ini. */
struct SimTurntableOptions
{
	double step_deg = 45;          ///< rotation per step (thesis: 45°, 8 views)
	double axis_distance_m = 0.6;  ///< from C0 to the rotation axis, horizontally
	double top_below_c0_m = 0.3;   ///< disc top below the head centre C0
	double disc_radius_m = 0.15;
	double disc_grey = 0.7;      ///< grey level 0..1 of the disc (a light rig: dark objects show)
	double backdrop_grey = 0.5;  ///< grey of a screen behind the object (0 = none, black)
	double backdrop_behind_m = 0.5;  ///< screen distance behind the rotation axis

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

class SimTurntable : public hw::TurntableDevice
{
 public:
	SimTurntable(StereoRenderer& renderer, const world::ObjectShape& shape,
	             const SimTurntableOptions& options);

	void rotateBy(double step_deg) override;
	double angleDeg() const override { return angle_deg_; }
	hw::StereoImages grab() override;

	/** Fixed head angles: symmetric fixation on the object's mid-height on the axis. */
	const geometry::HeadAngles& headAngles() const { return angles_; }
	/** Pose of the turntable frame T in C0 and in the left camera L (the calibration, thesis
	 * axes for C0 and L, metres). C0 is also W here. */
	Eigen::Isometry3d T_TinC0() const;
	Eigen::Isometry3d T_TinL() const;
	/** Pose of the object in L at the current angle: T_TinL · Rz(angle). */
	Eigen::Isometry3d T_OinL() const;

 private:
	StereoRenderer& renderer_;
	SimTurntableOptions options_;
	mrpt::opengl::COpenGLScene::Ptr scene_;
	mrpt::opengl::CSetOfObjects::Ptr object_;
	geometry::HeadAngles angles_;
	double angle_deg_ = 0;
	uint64_t frames_ = 0;
	void placeObject();
	mrpt::opengl::CBox::Ptr backdrop() const;
};

}  // namespace mrolr::sim
