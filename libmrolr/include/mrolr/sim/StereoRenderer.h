#pragma once
/** Headless stereo rendering of the lab from the two cameras of the BiSight head (thesis 4.2.2):
 * mrpt::opengl::CFBORender (its own EGL context, Mesa software rendering on machines without a GPU)
 * with the pinhole intrinsics of BiSightOptions. Greyscale images as the thesis's cameras gave, a
 * depth image of the left camera, optional Gaussian noise and blur, deterministic for a seed. */

#include <mrolr/geometry/BiSightHead.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/img/CImage.h>
#include <mrpt/math/CMatrixF.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>

namespace mrpt::opengl
{
class CFBORender;
}

namespace mrolr::sim
{
/** Rendering options, section [render] of config/sim.ini. */
struct RenderOptions
{
	double noise_sigma_grey = 0;  ///< std of additive Gaussian noise, grey levels (0 = none)
	double blur_sigma_px = 0;     ///< std of a Gaussian blur, pixels (0 = none)
	unsigned seed = 1;            ///< noise seed; frame k uses seed + k
	double clip_near_m = 0.1;     ///< nearest rendered depth
	double clip_far_m = 20;       ///< farthest rendered depth
	double light_ambient = 0.55;  ///< ambient light intensity 0..1
	double light_diffuse = 0.6;   ///< diffuse light intensity 0..1

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One rendered stereo pair. Camera poses are in W with thesis axes (x left, y up, z forward). */
struct StereoFrame
{
	mrpt::img::CImage left, right;          ///< 8-bit greyscale
	mrpt::math::CMatrixFloat depth_left_m;   ///< z depth per left pixel (m); 0 where nothing
	mrpt::math::CMatrixFloat depth_right_m;  ///< the same for the right camera (both-camera truth)
	Eigen::Isometry3d T_LinW = Eigen::Isometry3d::Identity();
	Eigen::Isometry3d T_RinW = Eigen::Isometry3d::Identity();
	double render_s = 0;  ///< wall-clock time spent rendering (reported apart from processing)
};

/** Renders stereo pairs of one scene. Not thread-safe (one EGL context per renderer). The scene
 * passed to render() must stay alive and unchanged between calls (its objects are shared). */
class StereoRenderer
{
 public:
	StereoRenderer(const geometry::BiSightHead& head, const RenderOptions& options);
	~StereoRenderer();

	/** The pair seen with the head centre at @p T_C0inW (thesis axes) and joint angles @p angles;
	 * @p frame_index selects the noise sample. */
	StereoFrame render(const mrpt::opengl::COpenGLScene& scene, const Eigen::Isometry3d& T_C0inW,
	                   const geometry::HeadAngles& angles, uint64_t frame_index = 0);

	/** One greyscale image (and optionally its depth) from a camera whose computer-vision pose
	 * (x right, y down, z forward) in W is @p T_CamCvInW; no noise. */
	mrpt::img::CImage renderView(const mrpt::opengl::COpenGLScene& scene,
	                             const Eigen::Isometry3d& T_CamCvInW,
	                             mrpt::math::CMatrixFloat* depth_m = nullptr);

	const geometry::BiSightHead& head() const { return head_; }
	const RenderOptions& options() const { return options_; }

 private:
	void degrade(mrpt::img::CImage& img, uint64_t sample) const;
	void wrap(const mrpt::opengl::COpenGLScene& scene);
	void setLights(const Eigen::Matrix3d& R_WinCam_mrpt);

	geometry::BiSightHead head_;
	RenderOptions options_;
	std::unique_ptr<mrpt::opengl::CFBORender> fbo_;
	mrpt::opengl::COpenGLViewport::Ptr wrapped_source_;
	mrpt::opengl::COpenGLScene::Ptr wrapped_;
	mrpt::opengl::CSetOfObjects::Ptr root_;
};

/** Grey image of a rendered colour image with the ITU-R BT.601 luminance weights
 *  (0.299 R + 0.587 G + 0.114 B), honouring the channel order the image declares; a grey image is
 *  copied unchanged. (MRPT's CImage::grayscale() swaps red and blue on CFBORender's BGR images.) */
mrpt::img::CImage toLuminance(const mrpt::img::CImage& rgb);

}  // namespace mrolr::sim
