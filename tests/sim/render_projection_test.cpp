// The rendered image of a known 3D point lands where the head model predicts (issue 4), and
// rendering is deterministic for a seed.
#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/StereoRenderer.h>

#include <mrpt/opengl/CSphere.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr;

namespace
{
/** Intensity-weighted centroid of the pixels brighter than 0 (the marker on black). */
Eigen::Vector2d centroid(const mrpt::img::CImage& img, double& weight)
{
	double sx = 0, sy = 0;
	weight = 0;
	for (int y = 0; y < int(img.getHeight()); ++y)
		for (int x = 0; x < int(img.getWidth()); ++x)
		{
			const double v = *img(x, y);
			sx += v * x, sy += v * y, weight += v;
		}
	return {sx / weight, sy / weight};
}

// large enough (about 8 px radius at 2 m) that pixel quantisation does not move the centroid; the
// perspective shift of a sphere's outline centre is (r/z)² times the offset, far below 0.01 px
constexpr double kRadius_m = 0.035;
// the issue asks for 0.5 px; the renderer achieves about 0.15 px, so the test holds it to 0.25 px
constexpr double kTolerance_px = 0.25;

sim::RenderOptions flatLight()
{
	sim::RenderOptions o;
	o.light_ambient = 1.0;  // uniform brightness: the centroid is not pulled by shading
	o.light_diffuse = 0.0;
	return o;
}
}  // namespace

TEST(RenderProjection, MarkerLandsWhereTheHeadModelPredicts)
{
	const geometry::BiSightHead head;
	sim::StereoRenderer renderer(head, flatLight());
	std::mt19937 rng(42);
	std::uniform_real_distribution<double> u(-1, 1);
	for (int trial = 0; trial < 8; ++trial)
	{
		const Eigen::Vector3d xv(u(rng), u(rng), u(rng) * M_PI);
		const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(xv, head.options().head_height_m);
		const Eigen::Vector3d p_C0(0.8 * u(rng), 0.5 * u(rng), 2.0 + 0.8 * u(rng));
		geometry::HeadAngles a = head.fixate(p_C0);
		a.pan += 0.15 * u(rng), a.tilt += 0.12 * u(rng);  // the point lands off-centre
		a.verg_left += 0.02 * u(rng), a.verg_right += 0.02 * u(rng);
		const Eigen::Vector3d p_W = T_C0inW * p_C0;
		mrpt::opengl::COpenGLScene scene;
		auto s = mrpt::opengl::CSphere::Create(float(kRadius_m), 48);
		s->setLocation(geometry::pointToMrpt(p_W));
		scene.insert(s);
		const auto f = renderer.render(scene, T_C0inW, a);
		const auto px = head.project(p_C0, a);
		double wl = 0, wr = 0;
		const Eigen::Vector2d cl = centroid(f.left, wl), cr = centroid(f.right, wr);
		ASSERT_GT(wl, 0) << "marker not rendered in the left image, trial " << trial;
		ASSERT_GT(wr, 0) << "marker not rendered in the right image, trial " << trial;
		EXPECT_LT((cl - Eigen::Vector2d(px.uL, px.vL)).norm(), kTolerance_px) << "trial " << trial;
		EXPECT_LT((cr - Eigen::Vector2d(px.uR, px.vR)).norm(), kTolerance_px) << "trial " << trial;
		// and the depth image holds the marker's depth along the left optic axis (1%)
		const double z = head.pointInCamera(geometry::Side::Left, p_C0, a).z();
		const float d = f.depth_left_m(int(std::lround(cl.y())), int(std::lround(cl.x())));
		EXPECT_NEAR(d, z - kRadius_m, 0.01 * z) << "trial " << trial;
	}
}

TEST(RenderProjection, DeterministicForASeedAndNoiseChangesWithIt)
{
	const geometry::BiSightHead head;
	sim::RenderOptions o;
	o.noise_sigma_grey = 3;
	o.blur_sigma_px = 0.8;
	const auto w = world::World::load(std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini");
	const auto lab = sim::buildLabScene(w);
	const Eigen::Isometry3d T = geometry::T_C0inW({0, 0, 0}, 1.0);
	const geometry::HeadAngles a{0.05, -0.2, -0.05, 0.05};
	sim::StereoRenderer r1(head, o), r2(head, o);
	const auto f1 = r1.render(*lab.scene, T, a, 3), f2 = r2.render(*lab.scene, T, a, 3);
	const auto f3 = r1.render(*lab.scene, T, a, 4);
	auto same = [](const mrpt::img::CImage& x, const mrpt::img::CImage& y)
	{
		for (unsigned r = 0; r < x.getHeight(); ++r)
			for (unsigned c = 0; c < x.getWidth(); ++c)
				if (*x(c, r) != *y(c, r)) return false;
		return true;
	};
	EXPECT_TRUE(same(f1.left, f2.left));
	EXPECT_TRUE(same(f1.right, f2.right));
	EXPECT_FALSE(same(f1.left, f3.left));  // another frame, another noise sample
	EXPECT_GT(f1.render_s, 0);
}

namespace
{
/** Grey level at the image centre of a sphere of `rgb` colour filling the view, lit uniformly. */
int centreGrey(const Eigen::Vector3d& rgb)
{
	const geometry::BiSightHead head;
	sim::StereoRenderer renderer(head, flatLight());
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW({0, 0, 0}, 1.0);
	const Eigen::Vector3d p_C0(0, 0, 1.0);
	const geometry::HeadAngles a = head.fixate(p_C0);
	mrpt::opengl::COpenGLScene scene;
	auto s = mrpt::opengl::CSphere::Create(0.2f, 48);
	s->setLocation(geometry::pointToMrpt(T_C0inW * p_C0));
	s->setColor(float(rgb[0]), float(rgb[1]), float(rgb[2]));
	scene.insert(s);
	const auto f = renderer.render(scene, T_C0inW, a);
	return *f.left(int(f.left.getWidth() / 2), int(f.left.getHeight() / 2));
}
}  // namespace

// A red object is as bright as its luminance (0.299 R + 0.587 G + 0.114 B), not as dark as a blue
// one: MRPT's CImage::grayscale() swaps red and blue on the renderer's BGR images.
TEST(RenderProjection, GreyIsTheLuminanceOfTheColour)
{
	const int white = centreGrey({1, 1, 1});
	const int red = centreGrey({1, 0, 0}), green = centreGrey({0, 1, 0}), blue = centreGrey({0, 0, 1});
	ASSERT_GT(white, 200);
	EXPECT_NEAR(red, 0.299 * white, 3);
	EXPECT_NEAR(green, 0.587 * white, 3);
	EXPECT_NEAR(blue, 0.114 * white, 3);
	EXPECT_GT(red, 2 * blue);
}

TEST(RenderProjection, LuminanceOfAGreyImageIsAPlainCopy)
{
	mrpt::img::CImage g(4, 3, mrpt::img::CH_GRAY);
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) *g(c, r) = uint8_t(10 * r + c);
	const auto out = sim::toLuminance(g);
	ASSERT_FALSE(out.isColor());
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 4; ++c) EXPECT_EQ(*out(c, r), 10 * r + c);
}
