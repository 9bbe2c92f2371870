#pragma once
/** Quality of a reconstructed wire-frame against the exact one (docs/model.md "Quality"): the fraction of
 * the true edge length recovered, false segments, endpoint error and conic radius error. Both
 * models must be in the same frame and in mm.
 *
 * - A true edge point (sampled every sample_step_mm) is recovered when a model feature passes
 * within tol_mm of it with a tangent within max_angle_deg.
 * - A model feature is false when less than half of its length lies within tol_mm of the truth.
 * - Endpoint error: distance (mm) of each endpoint of a non-false model line from the nearest true
 *   feature (a partial segment is not penalised for being short, only for being off the edge).
 * - Conic radius error: for each non-false model conic, max(|a − a_true|, |b − b_true|) against the
 *   true conic with the nearest centre and a parallel plane (|n·n_true| > 0.9). */

#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::model
{
struct QualityOptions
{
	double tol_mm = 5;
	double max_angle_deg = 20;
	double sample_step_mm = 2;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

struct ModelQuality
{
	double true_length_mm = 0, recovered_length_mm = 0;
	double recovered_fraction = 0;  ///< recovered / true length, 0..1
	int model_features = 0, false_features = 0;
	double median_endpoint_error_mm = 0, max_endpoint_error_mm = 0;
	int conics_compared = 0;
	double median_conic_radius_error_mm = 0;
	std::vector<double> endpoint_errors_mm, conic_radius_errors_mm;
};

/** Compares @p model with @p truth. */
ModelQuality compareToTruth(const WireFrame& model, const WireFrame& truth,
                            const QualityOptions& options = {});

/** How much of one true feature a model recovers (ModelQuality per feature; the breakdown of
 * what a scene model misses, `mrolr-model stats --per-feature`). */
struct FeatureRecovery
{
	bool conic = false;  ///< a conic of the truth (else a line)
	int id = 0;          ///< the truth feature's id
	double length_mm = 0, recovered_mm = 0;
	Eigen::Vector3d p1 = Eigen::Vector3d::Zero(), p2 = Eigen::Vector3d::Zero();  ///< line ends
	Eigen::Vector3d mid = Eigen::Vector3d::Zero();  ///< mean of the feature's samples
};

/** The recovered length of every true feature, lines first then conics, as compareToTruth counts
 * it (same samples, tolerance and tangent rule). */
std::vector<FeatureRecovery> recoveryPerFeature(const WireFrame& model, const WireFrame& truth,
                                                const QualityOptions& options = {});

/** Text table of the figures (one "key value" per line). */
void printQuality(const ModelQuality& q, std::ostream& out);

/** Median of a list (0 for an empty one). */
double median(std::vector<double> v);

}  // namespace mrolr::model
