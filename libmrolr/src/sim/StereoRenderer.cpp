#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/opengl/CFBORender.h>

#include <opencv2/imgproc.hpp>

#include <chrono>
#include <ostream>

namespace mrolr::sim
{
namespace
{
using O = RenderOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& renderOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("noise_sigma_grey", &O::noise_sigma_grey, 0, 100, kOpt)
	    .number("blur_sigma_px", &O::blur_sigma_px, 0, 20, kOpt)
	    .integer("seed", &O::seed, 0, 4294967295L, kOpt)
	    .number("clip_near_m", &O::clip_near_m, 1e-3, 1e6, kOpt)
	    .number("clip_far_m", &O::clip_far_m, 1e-3, 1e6, kOpt)
	    .number("light_ambient", &O::light_ambient, 0, 1, kOpt)
	    .number("light_diffuse", &O::light_diffuse, 0, 1, kOpt);
	return b;
}
}  // namespace

void RenderOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	renderOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "clip_near_m", clip_near_m, 1e-3, clip_far_m);
}

void RenderOptions::dump(std::ostream& out) const
{
	renderOptionsBinder().dump(out, *this);
}

StereoRenderer::StereoRenderer(const geometry::BiSightHead& head, const RenderOptions& options)
    : head_(head), options_(options)
{
	const auto& cam = head_.camera();
	fbo_ =
	    std::make_unique<mrpt::opengl::CFBORender>(unsigned(cam.width_px), unsigned(cam.height_px));
}

StereoRenderer::~StereoRenderer() = default;

void StereoRenderer::wrap(const mrpt::opengl::COpenGLScene& scene)
{
	// MRPT 2.5.8 loses up to ~0.25 px when it builds the view from a rotated 6-DOF camera pose
	// (measured against the head model), but projects exactly from the identity pose; so the camera
	// stays at the origin and the whole scene is moved by the inverse camera pose instead.
	// holding the source viewport keeps its address from being reused by a later scene
	if (wrapped_source_ == scene.getViewport()) return;
	wrapped_ = mrpt::opengl::COpenGLScene::Create();
	root_ = mrpt::opengl::CSetOfObjects::Create();
	for (const auto& o : *scene.getViewport()) root_->insert(o);
	wrapped_->insert(root_);
	wrapped_source_ = scene.getViewport();
}

void StereoRenderer::setLights(const Eigen::Matrix3d& R_WinCam_mrpt)
{
	auto vp = wrapped_->getViewport();
	vp->setViewportClipDistances(float(options_.clip_near_m), float(options_.clip_far_m));
	vp->setCustomBackgroundColor({0.f, 0.f, 0.f});
	auto& light = vp->lightParameters();
	const float a = float(options_.light_ambient), d = float(options_.light_diffuse);
	light.ambient = {a, a, a, 1.f};
	light.diffuse = {d, d, d, 1.f};
	light.specular = {0.f, 0.f, 0.f, 1.f};  // matte surfaces (thesis 7.2.2: no glare)
	// a fixed light in W (MRPT axes: from above, slightly from the front-left), seen from the
	// camera
	const Eigen::Vector3d dir = R_WinCam_mrpt * Eigen::Vector3d(0.3, -0.4, -0.866).normalized();
	light.direction = {float(dir.x()), float(dir.y()), float(dir.z())};
}

mrpt::img::CImage StereoRenderer::renderView(const mrpt::opengl::COpenGLScene& scene,
                                             const Eigen::Isometry3d& T_CamCvInW,
                                             mrpt::math::CMatrixFloat* depth_m)
{
	wrap(scene);
	// OpenGL puts pixel centres at half-integers; the head model (like OpenCV) at integers, so the
	// principal point is shifted by half a pixel for the renderer.
	mrpt::img::TCamera tc = head_.camera().toTCamera();
	tc.cx(tc.cx() + 0.5);
	tc.cy(tc.cy() + 0.5);
	const mrpt::poses::CPose3D camInW = geometry::cameraPoseToMrpt(T_CamCvInW);
	const mrpt::poses::CPose3D wInCam = -camInW;
	root_->setPose(wInCam);
	setLights(wInCam.getRotationMatrix().asEigen());
	auto& c = fbo_->getCamera(*wrapped_);
	c.setProjectiveFromPinhole(tc);
	c.set6DOFMode(true);
	c.setPose(mrpt::poses::CPose3D());
	mrpt::img::CImage rgb;
	if (depth_m)
		fbo_->render_RGBD(*wrapped_, rgb, *depth_m);
	else
		fbo_->render_RGB(*wrapped_, rgb);
	return toLuminance(rgb);
}

mrpt::img::CImage toLuminance(const mrpt::img::CImage& rgb)
{
	if (!rgb.isColor()) return rgb.makeDeepCopy();
	// CImage::grayscale() weighs the first stored channel by 0.299, but CFBORender stores blue
	// first (getChannelsOrder() says "BGR"): a red object came out as dark as a blue one. Convert
	// with the order the image declares.
	const cv::Mat m = rgb.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const bool bgr = rgb.getChannelsOrder() == std::string("BGR");
	cv::Mat g;
	cv::cvtColor(m, g, bgr ? cv::COLOR_BGR2GRAY : cv::COLOR_RGB2GRAY);
	return mrpt::img::CImage(g, mrpt::img::DEEP_COPY);
}

void StereoRenderer::degrade(mrpt::img::CImage& img, uint64_t sample) const
{
	if (options_.blur_sigma_px <= 0 && options_.noise_sigma_grey <= 0) return;
	cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY).clone();
	if (options_.blur_sigma_px > 0) cv::GaussianBlur(m, m, cv::Size(0, 0), options_.blur_sigma_px);
	if (options_.noise_sigma_grey > 0)
	{
		cv::Mat n(m.size(), CV_16SC1);
		cv::RNG rng(options_.seed + sample);
		rng.fill(n, cv::RNG::NORMAL, 0, options_.noise_sigma_grey);
		cv::Mat s;
		m.convertTo(s, CV_16SC1);
		s += n;
		s.convertTo(m, CV_8UC1);  // saturates to 0..255
	}
	img = mrpt::img::CImage(m, mrpt::img::DEEP_COPY);
}

StereoFrame StereoRenderer::render(const mrpt::opengl::COpenGLScene& scene,
                                   const Eigen::Isometry3d& T_C0inW,
                                   const geometry::HeadAngles& angles, uint64_t frame_index)
{
	using geometry::Side;
	const auto t0 = std::chrono::steady_clock::now();
	StereoFrame f;
	f.T_LinW = T_C0inW * head_.T_LinC0(angles);
	f.T_RinW = T_C0inW * head_.T_RinC0(angles);
	f.left = renderView(scene, T_C0inW * head_.T_CamCvInC0(Side::Left, angles), &f.depth_left_m);
	f.right = renderView(scene, T_C0inW * head_.T_CamCvInC0(Side::Right, angles), &f.depth_right_m);
	degrade(f.left, 2 * frame_index);
	degrade(f.right, 2 * frame_index + 1);
	f.render_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return f;
}

}  // namespace mrolr::sim
