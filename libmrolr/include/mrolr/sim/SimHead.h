#pragma once
/** The simulated BiSight head: joints move at limited speeds and settle before a grab; a grab
 * renders the stereo pair of the lab from the head's current camera poses. */

#include <mrolr/hw/Devices.h>
#include <mrolr/sim/StereoRenderer.h>

#include <mrpt/config/CConfigFileBase.h>

#include <functional>
#include <iosfwd>

namespace mrolr::sim
{
/** Section [sim_head] of config/sim.ini. */
struct SimHeadOptions
{
	double pan_speed_dps = 90;  ///< pan joint speed, degrees per second
	double tilt_speed_dps = 60;
	double vergence_speed_dps = 120;
	double settle_s = 0.05;  ///< time to settle after a move

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

class SimHead : public hw::HeadDevice
{
 public:
	/** @p T_C0inW gives the head centre's current true pose in W (from the simulated base). */
	SimHead(StereoRenderer& renderer, const mrpt::opengl::COpenGLScene& scene,
	        std::function<Eigen::Isometry3d()> T_C0inW, const SimHeadOptions& options);

	double moveTo(const geometry::HeadAngles& target) override;
	geometry::HeadAngles angles() const override { return angles_; }
	hw::StereoImages grab() override;

	/** The full frame of the last grab (depth, camera poses, rendering time). */
	const StereoFrame& lastFrame() const { return last_; }

 private:
	StereoRenderer& renderer_;
	const mrpt::opengl::COpenGLScene& scene_;
	std::function<Eigen::Isometry3d()> T_C0inW_;
	SimHeadOptions options_;
	geometry::HeadAngles angles_;
	uint64_t frames_ = 0;
	double time_s_ = 0;
	StereoFrame last_;
};

}  // namespace mrolr::sim
