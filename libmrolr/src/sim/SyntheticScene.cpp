#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Feature.h>
#include <mrolr/sim/SyntheticScene.h>

#include <algorithm>

namespace mrolr::sim
{
namespace
{
Eigen::Vector3d gaussian3(std::mt19937& rng, double sigma)
{
	std::normal_distribution<double> n(0, sigma > 0 ? sigma : 1e-300);
	return {n(rng), n(rng), n(rng)};
}

bool chance(std::mt19937& rng, double p)
{
	return std::uniform_real_distribution<>(0, 1)(rng) < p;
}

/** Hidden when on the far half of the object as seen along +z (the camera's optic axis). */
bool hidden(const Eigen::Vector3d& p, const Eigen::Vector3d& centroid, double extent)
{
	return p.z() - centroid.z() > 0.15 * extent;
}

void addLine(model::WireFrame& out, const model::Line3& l, const SceneNoise& n, std::mt19937& rng)
{
	std::vector<std::pair<double, double>> parts = {{0.0, 1.0}};
	if (chance(rng, n.fragment_probability))
	{
		const double cut = std::uniform_real_distribution<>(0.3, 0.7)(rng);
		parts = {{0.0, cut - 0.05}, {cut + 0.05, 1.0}};
	}
	for (const auto& [a, b] : parts)
	{
		model::Line3 f;
		f.id = static_cast<int>(out.lines.size() + out.conics.size()) + 1;
		f.p1 = l.p1 + a * (l.p2 - l.p1) + gaussian3(rng, n.endpoint_sigma_mm);
		f.p2 = l.p1 + b * (l.p2 - l.p1) + gaussian3(rng, n.endpoint_sigma_mm);
		if (chance(rng, n.flip_probability)) std::swap(f.p1, f.p2);
		out.lines.push_back(f);
	}
}

void addConic(model::WireFrame& out, model::Conic3 c, const SceneNoise& n, std::mt19937& rng)
{
	c.id = static_cast<int>(out.lines.size() + out.conics.size()) + 1;
	c.centre += gaussian3(rng, n.endpoint_sigma_mm);
	c.normal = (c.normal + gaussian3(rng, n.endpoint_sigma_mm / std::max(c.a, 1.0))).normalized();
	c.major = (c.major - c.major.dot(c.normal) * c.normal).normalized();  // keep it in the plane
	const double dr =
	    std::normal_distribution<>(0, n.endpoint_sigma_mm > 0 ? n.endpoint_sigma_mm : 1e-300)(rng);
	c.a += dr;
	c.b += dr;
	if (chance(rng, n.flip_probability))
	{
		c.normal = -c.normal;  // the same arc is traced with t -> -t
		std::tie(c.t1, c.t2) = std::make_pair(-c.t2, -c.t1);
	}
	out.conics.push_back(c);
}
}  // namespace

model::WireFrame corruptScene(const model::WireFrame& wf, const SceneNoise& noise,
                              std::mt19937& rng, double* visible_fraction)
{
	const auto fs = recog::featuresOf(wf);
	Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
	double extent = 0, total = 0, kept = 0;
	for (const auto& f : fs) centroid += f.m / static_cast<double>(fs.size());
	for (const auto& f : fs) extent = std::max(extent, 2 * (f.m - centroid).norm());
	model::WireFrame out;
	out.name = wf.name;
	out.frame = wf.frame;
	auto keep = [&](const Eigen::Vector3d& m, double len)
	{
		total += len;
		const bool k = !(noise.hide_back_side && hidden(m, centroid, extent)) &&
		               !chance(rng, noise.missing_fraction);
		if (k) kept += len;
		return k;
	};
	for (const auto& l : wf.lines)
		if (keep(0.5 * (l.p1 + l.p2), l.length())) addLine(out, l, noise, rng);
	for (const auto& c : wf.conics)
		if (keep(c.centre, model::arcLength(c))) addConic(out, c, noise, rng);
	if (visible_fraction) *visible_fraction = total > 0 ? kept / total : 0;
	return out;
}

void appendWireFrame(model::WireFrame& a, const model::WireFrame& b)
{
	int id = static_cast<int>(a.lines.size() + a.conics.size());
	for (const auto& l : a.lines) id = std::max(id, l.id);
	for (const auto& c : a.conics) id = std::max(id, c.id);
	for (auto l : b.lines) l.id = ++id, a.lines.push_back(l);
	for (auto c : b.conics) c.id = ++id, a.conics.push_back(c);
}

Eigen::Isometry3d tablePose(double yaw_deg, double tilt_deg, const Eigen::Vector3d& p_mm)
{
	// Object z (up) becomes the camera's +y (up); the table is seen from slightly above.
	const double d2r = M_PI / 180.0;
	const Eigen::Matrix3d upToY =
	    Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(tilt_deg * d2r, Eigen::Vector3d::UnitX()) * upToY *
	             Eigen::AngleAxisd(yaw_deg * d2r, Eigen::Vector3d::UnitZ());
	T.translation() = p_mm;
	return T;
}

TableScene makeTableScene(const std::vector<model::WireFrame>& objects, int target, int clutter,
                          const SceneNoise& noise, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<> yaw(0, 360), tilt(20, 40), depth(700, 1000);
	std::vector<int> chosen;
	if (target >= 0) chosen.push_back(target);
	std::vector<int> others;
	for (int k = 0; k < static_cast<int>(objects.size()); ++k)
		if (k != target) others.push_back(k);
	std::shuffle(others.begin(), others.end(), rng);
	for (int k = 0; k < clutter && k < static_cast<int>(others.size()); ++k)
		chosen.push_back(others[k]);
	std::vector<int> slots(chosen.size());
	for (size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
	std::shuffle(slots.begin(), slots.end(), rng);
	TableScene ts;
	ts.target = target;
	ts.scene.frame = model::WireFrameFrame::LeftCamera;
	for (size_t i = 0; i < chosen.size(); ++i)
	{
		const double x = 260.0 * (slots[i] - 0.5 * (static_cast<double>(slots.size()) - 1));
		const auto T = tablePose(yaw(rng), tilt(rng), Eigen::Vector3d(x, -150, depth(rng)));
		double visible = 0;
		const auto seen = corruptScene(placeInScene(objects[chosen[i]], T), noise, rng, &visible);
		appendWireFrame(ts.scene, seen);
		if (i == 0 && target >= 0) ts.T_OinS = T, ts.visible_fraction = visible;
	}
	return ts;
}

}  // namespace mrolr::sim
