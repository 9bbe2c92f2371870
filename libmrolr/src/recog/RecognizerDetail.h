#pragma once
// Internal to Recognizer*.cpp: the verification tolerances of a level and a verified hypothesis.

#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/recog/Verification.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace mrolr::recog::detail
{
inline double verifyBeta_mm(const LevelParams& p, const RecognitionOptions& o)
{
	return std::min(2 * p.position_error_mm, o.verify_position_error_mm);
}

inline double verifyTheta_rad(const LevelParams& p, const RecognitionOptions& o)
{
	return std::min(2 * p.rotation_deg, o.verify_rotation_deg) * M_PI / 180.0;
}

/** Verifies @p T against @p scene at level @p p, then re-estimates it by Faugeras–Hebert from all
 * verified correspondences while that helps (Recognizer.cpp). */
std::pair<Eigen::Isometry3d, VerificationResult> verifyAndRefine(
    const ModelTable& model, const std::vector<Feature>& scene, Eigen::Isometry3d T,
    const LevelParams& p, const RecognitionOptions& o, const SelfOcclusion* occ);

/** True when poses @p a and @p b (model → scene) carry the model point @p c_O less than
 * @p max_mm apart and differ by a rotation of less than @p max_deg. */
inline bool nearPose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                     const Eigen::Vector3d& c_O, double max_mm, double max_deg)
{
	const double angle = Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
	return (a * c_O - b * c_O).norm() < max_mm && angle < max_deg * M_PI / 180;
}

/** Adds the wall time of its scope (ms) to a stage of RecognitionTimes. */
class StageTimer
{
 public:
	explicit StageTimer(double& total_ms) : total_ms_(total_ms) {}
	StageTimer(const StageTimer&) = delete;
	StageTimer& operator=(const StageTimer&) = delete;
	~StageTimer()
	{
		total_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
		                                                       start_)
		                 .count();
	}

 private:
	double& total_ms_;
	std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/** Ranking of a verified pose: by its image score when there is one (3D score as tie-break). */
inline double rankOf(const VerificationResult& v, const std::optional<double>& image_score)
{
	return image_score ? *image_score + 0.05 * v.score : recog::rankOf(v);
}
}  // namespace mrolr::recog::detail
