#include <mrolr/recog/Verification.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
struct Support
{
	double overlap_mm = 0;
	const Feature* best = nullptr;
	double best_mm = 0;
};

/** Overlap (mm) of scene line s with model line l, or 0 when s is off the line. */
double lineOverlap(const Feature& l, const Feature& s, double beta, double cosT)
{
	if (std::abs(l.u.dot(s.u)) < cosT) return 0;
	auto perp = [&](const Eigen::Vector3d& p)
	{
		const Eigen::Vector3d w = p - l.m;
		return (w - w.dot(l.u) * l.u).norm();
	};
	if (perp(s.p1) > beta || perp(s.p2) > beta) return 0;
	double a = (s.p1 - l.m).dot(l.u), b = (s.p2 - l.m).dot(l.u);
	if (a > b) std::swap(a, b);
	return std::max(0.0, std::min(b, 0.5 * l.len_mm) - std::max(a, -0.5 * l.len_mm));
}

double conicOverlap(const Feature& c, const Feature& s, double beta, double cosT)
{
	if ((c.m - s.m).norm() > beta || std::abs(c.u.dot(s.u)) < cosT) return 0;
	const double rtol = beta;
	if (std::abs(c.a_mm - s.a_mm) > rtol || std::abs(c.b_mm - s.b_mm) > rtol) return 0;
	return std::min(c.len_mm, s.len_mm);
}

Support supportOf(const Feature& mf, const std::vector<Feature>& scene, double beta, double cosT)
{
	Support sup;
	for (const auto& s : scene)
	{
		if (s.kind != mf.kind) continue;
		const double o =
		    mf.isLine() ? lineOverlap(mf, s, beta, cosT) : conicOverlap(mf, s, beta, cosT);
		if (o <= 0) continue;
		sup.overlap_mm += o;
		if (o > sup.best_mm) sup.best_mm = o, sup.best = &s;
	}
	sup.overlap_mm = std::min(sup.overlap_mm, mf.len_mm);
	return sup;
}
}  // namespace

VerificationResult verifyPose(const ModelTable& model, const std::vector<Feature>& scene,
                              const Eigen::Isometry3d& T_OinS, double beta_mm, double theta_rad,
                              double min_len_mm, const SelfOcclusion* occlusion)
{
	VerificationResult r;
	const double cosT = std::cos(theta_rad);
	double total_mm = 0, touched_mm = 0;
	const std::vector<double> seen =
	    occlusion ? occlusion->visibleFractions(T_OinS.inverse().translation())
	              : std::vector<double>(model.features().size(), 1.0);
	for (size_t i = 0; i < model.features().size(); ++i)
	{
		const Feature& f = model.features()[i];
		if (f.len_mm < min_len_mm) continue;
		total_mm += seen[i] * f.len_mm;
		const Support sup = supportOf(f.transformed(T_OinS), scene, beta_mm, cosT);
		if (!sup.best) continue;
		r.supported_mm += sup.overlap_mm;
		touched_mm += f.len_mm;
		if (sup.overlap_mm >= 0.25 * f.len_mm) ++r.matched;
		const bool agree = (T_OinS.linear() * f.u).dot(sup.best->u) >= 0;
		r.correspondences.push_back({f, agree ? *sup.best : sup.best->flipped()});
	}
	r.considered_mm = total_mm;
	r.score = total_mm > 0 ? std::min(1.0, r.supported_mm / total_mm) : 0;
	r.coverage = touched_mm > 0 ? r.supported_mm / touched_mm : 0;
	return r;
}

}  // namespace mrolr::recog
