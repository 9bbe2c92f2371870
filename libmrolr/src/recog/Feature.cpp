#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Feature.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrolr::recog
{
namespace
{
bool finite(const Eigen::Vector3d& v)
{
	return v.allFinite();
}

[[noreturn]] void reject(const model::WireFrame& wf, const char* what, int id, const char* why)
{
	throw std::invalid_argument("wire-frame '" + wf.name + "': " + what + " " + std::to_string(id) +
	                            " " + why);
}

Feature lineFeature(const model::WireFrame& wf, const model::Line3& l)
{
	if (!finite(l.p1) || !finite(l.p2)) reject(wf, "line", l.id, "has non-finite endpoints");
	if (l.length() < 1e-9) reject(wf, "line", l.id, "has zero length");
	Feature f;
	f.kind = FeatureKind::Line;
	f.id = l.id;
	f.p1 = l.p1;
	f.p2 = l.p2;
	f.u = l.direction();
	f.m = 0.5 * (l.p1 + l.p2);
	f.len_mm = l.length();
	return f;
}

Feature conicFeature(const model::WireFrame& wf, const model::Conic3& c)
{
	if (!finite(c.centre) || !finite(c.normal) || !finite(c.major) || !std::isfinite(c.a) ||
	    !std::isfinite(c.b) || !std::isfinite(c.t1) || !std::isfinite(c.t2))
		reject(wf, "conic", c.id, "has non-finite values");
	if (c.a <= 0 || c.b <= 0) reject(wf, "conic", c.id, "has a non-positive semi-axis");
	if (c.normal.norm() < 1e-9) reject(wf, "conic", c.id, "has a zero normal");
	Feature f;
	f.kind = FeatureKind::Conic;
	f.id = c.id;
	f.u = c.normal.normalized();
	f.m = f.p1 = f.p2 = c.centre;
	f.a_mm = std::max(c.a, c.b);
	f.b_mm = std::min(c.a, c.b);
	f.len_mm = model::arcLength(c);
	if (f.len_mm < 1e-9) reject(wf, "conic", c.id, "has an empty arc");
	return f;
}
}  // namespace

Feature Feature::flipped() const
{
	Feature f = *this;
	f.u = -u;
	std::swap(f.p1, f.p2);
	return f;
}

Feature Feature::transformed(const Eigen::Isometry3d& T) const
{
	Feature f = *this;
	f.u = T.linear() * u;
	f.m = T * m;
	f.p1 = T * p1;
	f.p2 = T * p2;
	return f;
}

std::vector<Feature> featuresOf(const model::WireFrame& wf)
{
	std::vector<Feature> out;
	out.reserve(wf.lines.size() + wf.conics.size());
	for (const auto& l : wf.lines) out.push_back(lineFeature(wf, l));
	for (const auto& c : wf.conics) out.push_back(conicFeature(wf, c));
	return out;
}

}  // namespace mrolr::recog
