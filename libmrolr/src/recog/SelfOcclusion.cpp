#include <mrolr/recog/SelfOcclusion.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::recog
{
namespace
{
constexpr int kSamplesPerFeature = 8;
}  // namespace

std::vector<Eigen::Vector3d> sphereDirections(int n)
{
	std::vector<Eigen::Vector3d> dirs;
	const double golden = M_PI * (3.0 - std::sqrt(5.0));
	for (int i = 0; i < n; ++i)
	{
		const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
		dirs.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
	}
	return dirs;
}

std::vector<Eigen::Vector3d> samplesOf(const Feature& f, int count)
{
	std::vector<Eigen::Vector3d> pts;
	if (f.isLine())
	{
		for (int i = 0; i < count; ++i) pts.push_back(f.p1 + (f.p2 - f.p1) * (i + 0.5) / count);
		return pts;
	}
	const Eigen::Vector3d a = f.u.unitOrthogonal(), b = f.u.cross(a);
	const double r = 0.5 * (f.a_mm + f.b_mm);
	for (int i = 0; i < count; ++i)
	{
		const double t = 2 * M_PI * i / count;
		pts.push_back(f.m + r * (std::cos(t) * a + std::sin(t) * b));
	}
	return pts;
}

SelfOcclusion::SelfOcclusion(const std::vector<Feature>& features_O, double margin_mm,
                             int directions)
    : normals_(sphereDirections(directions)),
      bodies_(revolutionBodiesOf(features_O)),
      margin_mm_(margin_mm)
{
	for (const auto& f : features_O) samples_.push_back(samplesOf(f, kSamplesPerFeature));
	offsets_ = offsetsOf(samples_, margin_mm);
	if (bodies_.empty()) return;
	// the features off the bodies' surfaces (a cup's handle): they can hide a limb
	std::vector<std::vector<Eigen::Vector3d>> rest;
	for (const auto& fs : samples_)
	{
		const auto on = [&](const Eigen::Vector3d& p)
		{
			return std::any_of(bodies_.begin(), bodies_.end(),
			                   [&](const RevolutionBody& b) { return onSurface(b, p, margin_mm); });
		};
		if (!std::all_of(fs.begin(), fs.end(), on)) rest.push_back(fs);
	}
	if (!rest.empty()) rest_offsets_ = offsetsOf(rest, margin_mm);
}

std::vector<double> SelfOcclusion::offsetsOf(const std::vector<std::vector<Eigen::Vector3d>>& pts,
                                             double margin_mm) const
{
	std::vector<double> out;
	for (const auto& n : normals_)
	{
		double d = -std::numeric_limits<double>::infinity();
		for (const auto& fs : pts)
			for (const auto& p : fs) d = std::max(d, n.dot(p));
		out.push_back(d - margin_mm);
	}
	return out;
}

bool SelfOcclusion::hidden(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	return crossesPolytope(offsets_, c_O, p_O);
}

bool SelfOcclusion::contains(const Eigen::Vector3d& p_O) const
{
	for (size_t i = 0; i < normals_.size(); ++i)
		if (normals_[i].dot(p_O) > offsets_[i]) return false;
	return !normals_.empty();
}

bool SelfOcclusion::hiddenLimb(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	return !rest_offsets_.empty() && crossesPolytope(rest_offsets_, c_O, p_O);
}

bool SelfOcclusion::crossesPolytope(const std::vector<double>& offsets, const Eigen::Vector3d& c_O,
                                    const Eigen::Vector3d& p_O) const
{
	// Cyrus–Beck clipping of x(t) = c + t (p − c), t in [0, 1], against n·x <= d.
	const Eigen::Vector3d v = p_O - c_O;
	double t0 = 0, t1 = 1;
	for (size_t i = 0; i < normals_.size() && t0 < t1; ++i)
	{
		const double den = normals_[i].dot(v), num = offsets[i] - normals_[i].dot(c_O);
		if (std::abs(den) < 1e-12)
		{
			if (num < 0) return false;
			continue;
		}
		if (den > 0)
			t1 = std::min(t1, num / den);
		else
			t0 = std::max(t0, num / den);
	}
	return t0 < t1;
}

bool SelfOcclusion::hiddenOnBodies(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const
{
	bool on_body = false;
	for (const auto& b : bodies_)
	{
		if (!onSurface(b, p_O, margin_mm_)) continue;
		on_body = true;
		if (crossesSolid(b, c_O, p_O, margin_mm_)) return true;
	}
	return on_body ? false : hidden(c_O, p_O);
}

std::vector<double> SelfOcclusion::visibleFractions(const Eigen::Vector3d& c_O) const
{
	std::vector<double> out;
	for (const auto& fs : samples_)
	{
		int seen = 0;
		for (const auto& p : fs) seen += hidden(c_O, p) ? 0 : 1;
		out.push_back(fs.empty() ? 1.0 : static_cast<double>(seen) / fs.size());
	}
	return out;
}

}  // namespace mrolr::recog
