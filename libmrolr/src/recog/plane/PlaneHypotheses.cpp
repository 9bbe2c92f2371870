// Pose hypotheses from one scene feature on the support plane (PlaneHypotheses.h).
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/plane/PlaneHypotheses.h>

#include "../UprightPose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrolr::recog
{
namespace
{
constexpr double kDeg = M_PI / 180;
using detail::horizontalBasis;
using detail::standOn;
using detail::uprightRotation;

/** Angle of the horizontal part of @p d_S in the basis (h1, h2) of @p n. */
double horizontalAngle(const Eigen::Vector3d& d_S, const Eigen::Vector3d& n)
{
	const auto [h1, h2] = horizontalBasis(n);
	return std::atan2(d_S.dot(h2), d_S.dot(h1));
}

double meanRadius(const Feature& c)
{
	return 0.5 * (c.a_mm + c.b_mm);
}
}  // namespace

double modelBaseZ_mm(const model::WireFrame& model_O)
{
	double z = std::numeric_limits<double>::infinity();
	for (const auto& s : model::sampleWireFrame(model_O, 2)) z = std::min(z, s.p.z());
	if (!std::isfinite(z)) throw std::invalid_argument("model " + model_O.name + " has no edges");
	return z;
}

PlaneHypothesisGenerator::PlaneHypothesisGenerator(std::vector<Feature> model_O, double base_z_mm,
                                                   const PlaneHypothesisOptions& opts)
    : model_(std::move(model_O)), base_z_mm_(base_z_mm), opts_(opts)
{
	const double rim_cos = std::cos(opts_.rim_normal_tol_deg * kDeg);
	const double horiz_sin = std::sin(opts_.horizontal_tol_deg * kDeg);
	for (size_t i = 0; i < model_.size(); ++i)
	{
		const Feature& f = model_[i];
		if (!f.isLine() && std::abs(f.u.z()) >= rim_cos) rims_.push_back(i);
		if (f.isLine() && std::abs(f.u.z()) <= horiz_sin && f.len_mm >= opts_.min_line_mm)
			lines_.push_back(i);
	}
	if (opts_.limb_hypotheses) findLimbCylinders();
	if (opts_.edge_pair_hypotheses && cylinders_.empty()) findVerticalEdgePairs();
}

double PlaneHypothesisGenerator::baseOffset_mm(const Eigen::Isometry3d& T_OinS,
                                               const SupportPlane& plane) const
{
	return plane.height_mm(T_OinS * Eigen::Vector3d(0, 0, base_z_mm_));
}

void PlaneHypothesisGenerator::addRimHypotheses(size_t rim, size_t s, const Feature& conic,
                                                const SupportPlane& plane,
                                                std::vector<PlaneHypothesis>& out) const
{
	const Feature& m = model_[rim];
	// the rim's centre on the model's axis (a tilted rim's centre is off it by little)
	const Eigen::Vector3d c_O = m.m;
	const double step = std::max(1.0, opts_.rim_yaw_step_deg) * kDeg;
	for (double yaw = 0; yaw < 2 * M_PI - 1e-9; yaw += step)
	{
		PlaneHypothesis h;
		h.T_OinS.linear() = uprightRotation(plane.n_S, yaw);
		h.T_OinS.translation() =
		    standOn(conic.m - h.T_OinS.linear() * c_O, plane, base_z_mm_);
		h.from_rim = true;
		h.model_feature = static_cast<int>(rim);
		h.scene_feature = static_cast<int>(s);
		out.push_back(h);
	}
}

void PlaneHypothesisGenerator::addLineHypotheses(size_t line, size_t s, const Feature& sl,
                                                 const SupportPlane& plane,
                                                 std::vector<PlaneHypothesis>& out) const
{
	const Feature& ml = model_[line];
	const Eigen::Vector3d& n = plane.n_S;
	const double yaw0 =
	    horizontalAngle(sl.u, n) - std::atan2(ml.u.y(), ml.u.x());  // model dir onto scene dir
	for (const double yaw : {yaw0, yaw0 + M_PI})
	{
		const Eigen::Matrix3d R = uprightRotation(n, yaw);
		const Eigen::Vector3d w = (R * Eigen::Vector3d(ml.u.x(), ml.u.y(), 0)).normalized();
		const Eigen::Vector3d v = n.cross(w);
		const Eigen::Vector3d a = R * ml.p1, b = R * ml.p2;
		const double m_lo = std::min(w.dot(a), w.dot(b)), m_hi = std::max(w.dot(a), w.dot(b));
		const double s_lo = std::min(w.dot(sl.p1), w.dot(sl.p2));
		const double s_hi = std::max(w.dot(sl.p1), w.dot(sl.p2));
		const double t_v = v.dot(sl.m) - v.dot(R * ml.m);
		for (const double t_w :
		     {s_lo - m_lo, s_hi - m_hi, 0.5 * (s_lo + s_hi) - 0.5 * (m_lo + m_hi)})
		{
			PlaneHypothesis h;
			h.T_OinS.linear() = R;
			h.T_OinS.translation() = standOn(t_w * w + t_v * v, plane, base_z_mm_);
			h.model_feature = static_cast<int>(line);
			h.scene_feature = static_cast<int>(s);
			out.push_back(h);
		}
	}
}

std::vector<PlaneHypothesis> PlaneHypothesisGenerator::generate(
    const std::vector<Feature>& scene_S, const SupportPlane& plane) const
{
	std::vector<PlaneHypothesis> out;
	const double normal_cos = std::cos(opts_.scene_normal_tol_deg * kDeg);
	const double horiz_sin = std::sin(opts_.horizontal_tol_deg * kDeg);
	const double limb_cos = std::cos(opts_.limb_vertical_tol_deg * kDeg);
	std::vector<size_t> verticals;
	for (size_t s = 0; s < scene_S.size(); ++s)
	{
		const Feature& f = scene_S[s];
		const double h = plane.height_mm(f.m);
		const bool vertical = f.isLine() && f.len_mm >= opts_.limb_min_mm &&
		                      std::abs(f.u.dot(plane.n_S)) >= limb_cos;
		if (vertical) verticals.push_back(s);  // for the edge pairs
		if (vertical && !cylinders_.empty())
		{
			const double h1 = plane.height_mm(f.p1), h2 = plane.height_mm(f.p2);
			for (const LimbCylinder& c : cylinders_)
				if (std::min(h1, h2) >= c.z_lo_mm - base_z_mm_ - opts_.height_tol_mm &&
				    std::max(h1, h2) <= c.z_hi_mm - base_z_mm_ + opts_.height_tol_mm)
					addLimbHypotheses(c, s, f, plane, out);
			continue;
		}
		if (!f.isLine())
		{
			if (std::abs(f.u.dot(plane.n_S)) < normal_cos) continue;
			for (const size_t r : rims_)
				if (std::abs(meanRadius(f) - meanRadius(model_[r])) <= opts_.radius_tol_mm &&
				    std::abs(h - (model_[r].m.z() - base_z_mm_)) <= opts_.height_tol_mm)
					addRimHypotheses(r, s, f, plane, out);
			continue;
		}
		if (std::abs(f.u.dot(plane.n_S)) > horiz_sin || f.len_mm < opts_.min_line_mm) continue;
		for (const size_t l : lines_)
			if (f.len_mm <= opts_.max_length_ratio * model_[l].len_mm &&
			    std::abs(h - (model_[l].m.z() - base_z_mm_)) <= opts_.height_tol_mm)
				addLineHypotheses(l, s, f, plane, out);
	}
	if (!edge_pairs_.empty()) addEdgePairHypotheses(scene_S, verticals, plane, out);
	return out;
}

}  // namespace mrolr::recog
