#pragma once
/** The arithmetic of EdgeImage's walk over the samples of a pose (its forEachInView), for a run
 * of samples at a time so that the compiler vectorises it (MROLR_SIMD_CLONES): each sample's
 * point and the end of its tangent in the camera frame, whether both are in view, and their
 * pixels through the lens (cv::projectPoints's model, 5 coefficients). The same operations in the
 * same order as one sample at a time (Eigen's Isometry3d times a point, then the distortion in
 * OpenCV's order), so the same bits: the image scores do not change. */
#include <mrolr/recog/images/Limbs.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrolr::recog
{
struct ProjectedRun
{
	static constexpr size_t kMax = 16;  ///< samples per run
	size_t n = 0;
	double x[kMax], y[kMax], z[kMax];  ///< the sample in the camera frame (OpenCV's axes, mm)
	double u[kMax], v[kMax];           ///< its pixel
	double tu[kMax], tv[kMax];  ///< the pixel of its tangent's end (point + t_O) minus its own
	/// 1 when both ends are in front of the camera within 45° of its axis (inView), else 0 (a
	/// 64-bit flag: the vectoriser keeps one lane width)
	std::int64_t in_view[kMax];
};

/** True for a point of the camera frame (mm) in front of it, within 45° of its axis: points far
 * outside the view are dropped, since the distortion polynomial folds them back in. (One
 * expression without branches, for the vectoriser.) */
inline bool inView(double x, double y, double z)
{
	return (z > 1) & (std::abs(x) < z) & (std::abs(y) < z);
}

/** Up to ProjectedRun::kMax samples laid out as RunProjection reads them (one array per
 * coordinate): a model's samples are projected at every pose a score asks about, and transposed
 * once (SightedSamples). */
struct SampleBlock
{
	size_t n = 0;
	double p[3][ProjectedRun::kMax];  ///< the samples' points p_O by coordinate (mm)
	double d[3][ProjectedRun::kMax];  ///< their tangents t_O by coordinate
};

/** @p samples in blocks of ProjectedRun::kMax (the last one shorter). */
std::vector<SampleBlock> sampleBlocksOf(const std::vector<EdgeSample>& samples);

/** A pose of the camera and its lens as the projection of a run reads them: built once for a walk
 * over a pose's samples, then asked for each run. A lens without distortion (D all 0: an ideal or a
 * rectified camera) is projected without the polynomial, to the same bits: its terms are then 1
 * and 0 exactly for every point in view. */
class RunProjection
{
 public:
	/** The lens: intrinsics (px) and distortion. */
	struct Lens
	{
		double fx, fy, cx, cy, k1, k2, p1, p2, k3;
	};

	/** The camera with intrinsics @p K and distortion @p D (k1 k2 p1 p2 k3) at @p T_OinC. */
	RunProjection(const Eigen::Isometry3d& T_OinC, const cv::Matx33d& K,
	              const cv::Vec<double, 5>& D);
	/** Fills @p out for the samples of @p block. */
	void project(const SampleBlock& block, ProjectedRun& out) const;
	/** Fills @p out for the @p n <= ProjectedRun::kMax samples from @p first (more: throws
	 * std::invalid_argument). */
	void project(const EdgeSample* first, size_t n, ProjectedRun& out) const;

 private:
	std::array<double, 9> R_;  ///< column-major: R_[3 j + i] = R(i, j)
	std::array<double, 3> t_;  ///< mm
	Lens lens_;
	bool distorted_;
};

}  // namespace mrolr::recog
