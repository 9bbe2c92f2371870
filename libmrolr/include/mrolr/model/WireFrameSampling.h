#pragma once
/** Points sampled densely along the lines and conic arcs of a wire-frame, with their unit tangents:
 * the common ground of model statistics, duplicate merging and drawing. */

#include <mrolr/model/WireFrame.h>

#include <vector>

namespace mrolr::model
{
/** One sample: position (mm), unit tangent, and which feature it belongs to. */
struct FeatureSample
{
	Eigen::Vector3d p = Eigen::Vector3d::Zero();
	Eigen::Vector3d tangent = Eigen::Vector3d::UnitX();
	int feature = 0;       ///< index into lines, then conics (lines.size() + conic index)
	double weight_mm = 0;  ///< length of curve this sample stands for
};

/** Samples of one line, about @p step_mm apart (at least 2). */
std::vector<FeatureSample> sampleLine(const Line3& l, double step_mm, int feature);

/** Samples of one conic arc, about @p step_mm apart along the arc (at least 8). */
std::vector<FeatureSample> sampleConic(const Conic3& c, double step_mm, int feature);

/** Samples of every feature; feature index = line index or lines.size() + conic index. */
std::vector<FeatureSample> sampleWireFrame(const WireFrame& wf, double step_mm);

/** Distance (mm) from p to the nearest feature of @p wf (exact for lines, conics sampled every
 * 0.25 mm); infinity for an empty model. */
double distanceToWireFrame(const Eigen::Vector3d& p, const WireFrame& wf);

/** Arc length of a conic arc (mm), numerically. */
double arcLength(const Conic3& c);

/** Total length of lines and conic arcs (mm). */
double totalLength(const WireFrame& wf);

/** Number of features (lines + conics). */
inline size_t featureCount(const WireFrame& wf)
{
	return wf.lines.size() + wf.conics.size();
}

/** Id of feature index @p i (line or conic). */
int featureId(const WireFrame& wf, size_t i);

/** Largest id in use (0 for an empty model). */
int maxId(const WireFrame& wf);

}  // namespace mrolr::model
