#pragma once
/** A stand-in stereo head for tests and benchmarks: textured point features pasted, with sub-pixel
 * placement, where the BiSight head model projects them (thesis eq 4.24), on a flat grey
 * background with Gaussian pixel noise. Textures keep their image size at any distance, which is
 * the patch-matching assumption of 5.2.1 (no change of scale between views). */

#include <mrolr/vision/StereoHeadDevice.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace mrolr::vision
{
/** A scene point (C0, metres) and the texture that surrounds it in both images. */
struct TexturedPoint
{
	Eigen::Vector3d p_inC0 = Eigen::Vector3d::Zero();
	cv::Mat texture;  ///< CV_8UC1, odd sides; its centre pixel lands on the projected point
};

/** A random high-contrast texture of @p size_px × @p size_px (odd), reproducible from @p seed. */
cv::Mat makeTexture(int size_px, std::uint64_t seed);

/** Renders TexturedPoints into 8-bit stereo pairs for the head model it is given. */
class SyntheticStereoHead : public StereoHeadDevice
{
 public:
	/** @p noise_sigma: standard deviation of the pixel noise, grey levels; @p background: grey
	 * level. */
	SyntheticStereoHead(const geometry::BiSightHead& head, double noise_sigma = 2.0,
	                    std::uint64_t seed = 1, int background = 90);

	/** Replaces the scene (points in C0, so a moving base is simulated by updating them). */
	void setPoints(std::vector<TexturedPoint> points) { points_ = std::move(points); }
	const std::vector<TexturedPoint>& points() const { return points_; }

	void moveTo(const geometry::HeadAngles& angles) override;
	geometry::HeadAngles angles() const override { return angles_; }
	StereoImages grab() override;

	/** Renders one camera at @p angles without noise (deterministic). */
	cv::Mat render(geometry::Side side, const geometry::HeadAngles& angles) const;

 private:
	geometry::BiSightHead head_;
	double noise_sigma_;
	cv::RNG rng_;
	int background_;
	geometry::HeadAngles angles_;
	std::vector<TexturedPoint> points_;
};

}  // namespace mrolr::vision
