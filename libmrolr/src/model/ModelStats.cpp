#include <mrolr/model/ModelStats.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace mrolr::model
{
namespace
{
/** Is sample @p s within tol of some sample of @p others with a compatible tangent? */
bool covered(const FeatureSample& s, const std::vector<FeatureSample>& others, double tol,
             double min_cos)
{
	for (const auto& o : others)
		if ((o.p - s.p).squaredNorm() <= tol * tol && std::abs(o.tangent.dot(s.tangent)) >= min_cos)
			return true;
	return false;
}

/** Per model feature: the fraction of its length near the truth. */
std::vector<double> supportedFraction(const std::vector<FeatureSample>& model, size_t n_features,
                                      const std::vector<FeatureSample>& truth, double tol,
                                      double min_cos)
{
	std::vector<double> near(n_features, 0), all(n_features, 0);
	for (const auto& s : model)
	{
		all[s.feature] += s.weight_mm;
		if (covered(s, truth, tol, min_cos)) near[s.feature] += s.weight_mm;
	}
	for (size_t i = 0; i < n_features; ++i) near[i] = all[i] > 0 ? near[i] / all[i] : 0;
	return near;
}

double conicRadiusError(const Conic3& c, const WireFrame& truth)
{
	double best_d = std::numeric_limits<double>::infinity(), err = -1;
	for (const auto& t : truth.conics)
	{
		const double d = (t.centre - c.centre).norm();
		if (std::abs(t.normal.dot(c.normal)) > 0.9 && d < best_d)
			best_d = d, err = std::max(std::abs(c.a - t.a), std::abs(c.b - t.b));
	}
	return err;
}

/** Endpoint and radius errors of the model features that are not false. */
void featureErrors(const WireFrame& model, const WireFrame& truth,
                   const std::vector<double>& support, ModelQuality& q)
{
	for (size_t i = 0; i < model.lines.size(); ++i)
	{
		if (support[i] < 0.5) continue;
		q.endpoint_errors_mm.push_back(distanceToWireFrame(model.lines[i].p1, truth));
		q.endpoint_errors_mm.push_back(distanceToWireFrame(model.lines[i].p2, truth));
	}
	for (size_t j = 0; j < model.conics.size(); ++j)
	{
		if (support[model.lines.size() + j] < 0.5) continue;
		const double e = conicRadiusError(model.conics[j], truth);
		if (e >= 0) q.conic_radius_errors_mm.push_back(e);
	}
}
}  // namespace

namespace
{
using Q = QualityOptions;
constexpr auto kOpt = util::Presence::Optional;  // [quality]: every key of config/model.ini

const util::OptionsBinder<Q>& qualityOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<Q>()
	        .number("tol_mm", &Q::tol_mm, 1e-3, 1e4, kOpt)
	        .number("max_angle_deg", &Q::max_angle_deg, 0, 90, kOpt)
	        .number("sample_step_mm", &Q::sample_step_mm, 0.1, 1e3, kOpt);
	return b;
}
}  // namespace

void QualityOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	qualityOptionsBinder().load(cfg, section, *this);
}

double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	const auto mid = v.begin() + static_cast<long>(v.size() / 2);
	std::nth_element(v.begin(), mid, v.end());
	if (v.size() % 2) return *mid;
	return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

ModelQuality compareToTruth(const WireFrame& model, const WireFrame& truth, const QualityOptions& o)
{
	const double min_cos = std::cos(o.max_angle_deg * M_PI / 180);
	const auto ts = sampleWireFrame(truth, o.sample_step_mm);
	const auto ms = sampleWireFrame(model, o.sample_step_mm);
	ModelQuality q;
	for (const auto& s : ts)
	{
		q.true_length_mm += s.weight_mm;
		if (covered(s, ms, o.tol_mm, min_cos)) q.recovered_length_mm += s.weight_mm;
	}
	q.recovered_fraction = q.true_length_mm > 0 ? q.recovered_length_mm / q.true_length_mm : 0;
	const size_t n = model.lines.size() + model.conics.size();
	const auto support = supportedFraction(ms, n, ts, o.tol_mm, min_cos);
	q.model_features = static_cast<int>(n);
	q.false_features = static_cast<int>(
	    std::count_if(support.begin(), support.end(), [](double f) { return f < 0.5; }));
	featureErrors(model, truth, support, q);
	q.median_endpoint_error_mm = median(q.endpoint_errors_mm);
	for (double e : q.endpoint_errors_mm)
		q.max_endpoint_error_mm = std::max(q.max_endpoint_error_mm, e);
	q.conics_compared = static_cast<int>(q.conic_radius_errors_mm.size());
	q.median_conic_radius_error_mm = median(q.conic_radius_errors_mm);
	return q;
}

std::vector<FeatureRecovery> recoveryPerFeature(const WireFrame& model, const WireFrame& truth,
                                                const QualityOptions& o)
{
	const double min_cos = std::cos(o.max_angle_deg * M_PI / 180);
	const auto ts = sampleWireFrame(truth, o.sample_step_mm);
	const auto ms = sampleWireFrame(model, o.sample_step_mm);
	std::vector<FeatureRecovery> out(truth.lines.size() + truth.conics.size());
	for (size_t i = 0; i < truth.lines.size(); ++i)
		out[i].id = truth.lines[i].id, out[i].p1 = truth.lines[i].p1, out[i].p2 = truth.lines[i].p2;
	for (size_t j = 0; j < truth.conics.size(); ++j)
		out[truth.lines.size() + j].conic = true,
		                        out[truth.lines.size() + j].id = truth.conics[j].id;
	for (const auto& s : ts)
	{
		auto& f = out[s.feature];
		f.length_mm += s.weight_mm;
		f.mid += s.weight_mm * s.p;
		if (covered(s, ms, o.tol_mm, min_cos)) f.recovered_mm += s.weight_mm;
	}
	for (auto& f : out)
		if (f.length_mm > 0) f.mid /= f.length_mm;
	return out;
}

void printQuality(const ModelQuality& q, std::ostream& out)
{
	out << "true_length_mm " << q.true_length_mm << "\nrecovered_length_mm "
	    << q.recovered_length_mm << "\nrecovered_fraction " << q.recovered_fraction
	    << "\nmodel_features " << q.model_features << "\nfalse_features " << q.false_features
	    << "\nmedian_endpoint_error_mm " << q.median_endpoint_error_mm << "\nmax_endpoint_error_mm "
	    << q.max_endpoint_error_mm << "\nconics_compared " << q.conics_compared
	    << "\nmedian_conic_radius_error_mm " << q.median_conic_radius_error_mm << "\n";
}

}  // namespace mrolr::model
