#include <mrolr/model/WireFrameSampling.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::model
{
std::vector<FeatureSample> sampleLine(const Line3& l, double step_mm, int feature)
{
	const double len = l.length();
	const int n = std::max(2, static_cast<int>(std::ceil(len / step_mm)) + 1);
	std::vector<FeatureSample> out;
	const Eigen::Vector3d t = len > 0 ? l.direction() : Eigen::Vector3d::UnitX();
	for (int i = 0; i < n; ++i)
	{
		const double s = (i + 0.5) / n;  // midpoints of n equal pieces
		out.push_back({l.p1 + s * (l.p2 - l.p1), t, feature, len / n});
	}
	return out;
}

double arcLength(const Conic3& c)
{
	const int n = 256;
	double len = 0;
	for (int i = 0; i < n; ++i)
	{
		const double t0 = c.t1 + (c.t2 - c.t1) * i / n, t1 = c.t1 + (c.t2 - c.t1) * (i + 1) / n;
		len += (c.pointAt(t1) - c.pointAt(t0)).norm();
	}
	return len;
}

std::vector<FeatureSample> sampleConic(const Conic3& c, double step_mm, int feature)
{
	const double len = arcLength(c);
	const int n = std::max(8, static_cast<int>(std::ceil(len / step_mm)));
	std::vector<FeatureSample> out;
	for (int i = 0; i < n; ++i)
	{
		const double t = c.t1 + (c.t2 - c.t1) * (i + 0.5) / n;
		const Eigen::Vector3d d =
		    -c.a * std::sin(t) * c.major + c.b * std::cos(t) * c.normal.cross(c.major);
		out.push_back({c.pointAt(t), d.normalized(), feature, len / n});
	}
	return out;
}

std::vector<FeatureSample> sampleWireFrame(const WireFrame& wf, double step_mm)
{
	std::vector<FeatureSample> out;
	int k = 0;
	for (const auto& l : wf.lines)
	{
		const auto s = sampleLine(l, step_mm, k++);
		out.insert(out.end(), s.begin(), s.end());
	}
	for (const auto& c : wf.conics)
	{
		const auto s = sampleConic(c, step_mm, k++);
		out.insert(out.end(), s.begin(), s.end());
	}
	return out;
}

double totalLength(const WireFrame& wf)
{
	double len = 0;
	for (const auto& l : wf.lines) len += l.length();
	for (const auto& c : wf.conics) len += arcLength(c);
	return len;
}

double distanceToWireFrame(const Eigen::Vector3d& p, const WireFrame& wf)
{
	double best = std::numeric_limits<double>::infinity();
	for (const auto& l : wf.lines)
	{
		const Eigen::Vector3d ab = l.p2 - l.p1;
		const double t =
		    std::clamp((p - l.p1).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
		best = std::min(best, (l.p1 + t * ab - p).norm());
	}
	for (const auto& c : wf.conics)
		for (const auto& s : sampleConic(c, 0.25, 0)) best = std::min(best, (s.p - p).norm());
	return best;
}

int featureId(const WireFrame& wf, size_t i)
{
	return i < wf.lines.size() ? wf.lines[i].id : wf.conics.at(i - wf.lines.size()).id;
}

int maxId(const WireFrame& wf)
{
	int m = 0;
	for (const auto& l : wf.lines) m = std::max(m, l.id);
	for (const auto& c : wf.conics) m = std::max(m, c.id);
	return m;
}

}  // namespace mrolr::model
