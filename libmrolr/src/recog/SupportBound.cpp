#include <mrolr/recog/SupportBound.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
/** Length (mm) of the part of segment p1–p2 inside the ball (c, r). */
double lengthInBall(const Feature& s, const Eigen::Vector3d& c, double r)
{
	const Eigen::Vector3d w = s.p1 - c;
	const double b = w.dot(s.u), disc = b * b - (w.squaredNorm() - r * r);
	if (disc <= 0) return 0;
	const double t1 = std::max(0.0, -b - std::sqrt(disc)),
	             t2 = std::min(s.len_mm, -b + std::sqrt(disc));
	return std::max(0.0, t2 - t1);
}

/** Closest distance (mm) between the infinite lines of two line features. */
double lineLineDistance(const Feature& a, const Feature& b)
{
	const Eigen::Vector3d n = a.u.cross(b.u), w = b.m - a.m;
	if (n.norm() < 1e-9) return (w - w.dot(a.u) * a.u).norm();
	return std::abs(w.dot(n.normalized()));
}

bool nearlyCoincident(const Feature& a, const Feature& b, double beta, double cos2t)
{
	if (std::abs(a.u.dot(b.u)) < cos2t) return false;
	return a.isLine() ? lineLineDistance(a, b) <= 2 * beta : (a.m - b.m).norm() <= 2 * beta;
}

/** Samples every h along the lines (endpoints included) and the conic centres. */
std::vector<Eigen::Vector3d> samples(const std::vector<Feature>& scene, double h)
{
	std::vector<Eigen::Vector3d> out;
	for (const auto& s : scene)
	{
		const int m = s.isLine() ? static_cast<int>(std::ceil(s.len_mm / h)) : 0;
		for (int i = 0; i <= m; ++i)
			out.push_back(s.isLine() ? Eigen::Vector3d(s.p1 + (s.len_mm * i / m) * s.u) : s.m);
	}
	return out;
}
}  // namespace

SupportBound::SupportBound(const ModelTable& model, double beta_mm, double theta_rad)
    : model_(model), beta_mm_(beta_mm)
{
	for (const auto& f : model.features()) centroid_ += f.m;
	centroid_ /= static_cast<double>(std::max<size_t>(1, model.features().size()));
	for (const auto& f : model.features())
	{
		radius_mm_ = std::max(
		    radius_mm_, f.isLine() ? std::max((f.p1 - centroid_).norm(), (f.p2 - centroid_).norm())
		                           : (f.m - centroid_).norm() + f.a_mm);
		(f.isLine() ? lines_mm_ : conics_mm_) += f.len_mm;
		double& longest = f.isLine() ? longest_line_mm_ : longest_conic_mm_;
		longest = std::max(longest, f.len_mm);
	}
	k_lines_ = multiplicity(FeatureKind::Line, beta_mm, theta_rad);
	k_conics_ = multiplicity(FeatureKind::Conic, beta_mm, theta_rad);
}

int SupportBound::multiplicity(FeatureKind kind, double beta, double theta) const
{
	const auto& fs = model_.features();
	const double cos2t = std::cos(std::min(M_PI / 2, 2 * theta));
	int k = 0;
	for (const auto& a : fs)
	{
		if (a.kind != kind) continue;
		int n = 0;
		for (const auto& b : fs) n += b.kind == kind && nearlyCoincident(a, b, beta, cos2t);
		k = std::max(k, n);
	}
	return k;
}

double SupportBound::inBall_mm(const std::vector<Feature>& scene, const Eigen::Vector3d& p,
                               double r) const
{
	double sl = 0, sc = 0;
	for (const auto& s : scene)
		if (s.isLine())
			sl += std::min(lengthInBall(s, p, r), longest_line_mm_);
		else if ((s.m - p).norm() <= r)
			sc += std::min(s.len_mm, longest_conic_mm_);
	return std::min(lines_mm_, k_lines_ * sl) + std::min(conics_mm_, k_conics_ * sc);
}

double SupportBound::supportBound_mm(const std::vector<Feature>& scene) const
{
	const double rho = radius_mm_ + beta_mm_, h = rho / 2, r = 2 * rho + h / 2;
	double best = 0;
	for (const auto& p : samples(scene, h))
	{
		best = std::max(best, inBall_mm(scene, p, r));
		if (best >= lines_mm_ + conics_mm_) break;
	}
	return best;
}

double SupportBound::focusSupportBound_mm(const std::vector<Feature>& scene, size_t focus,
                                          const Feature& s0, double match_beta_mm) const
{
	const Feature& f = model_.features().at(focus);
	const double reach = (f.m - centroid_).norm() + (f.isLine() ? f.len_mm / 2 : 0.0);
	return inBall_mm(scene, s0.m, radius_mm_ + beta_mm_ + reach + 2 * match_beta_mm);
}

}  // namespace mrolr::recog
