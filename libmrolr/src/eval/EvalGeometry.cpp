#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/sim/ObjectWireFrame.h>

#include <algorithm>
#include <cmath>

namespace mrolr::eval
{
namespace
{
constexpr double kSymmetryTol_mm = 0.5;

/** Largest rendered depth (mm) in the 3×3 pixels around (u, v); 0 = nothing drawn there. */
double farthestDepth_mm(const mrpt::math::CMatrixFloat& depth_m, int u, int v)
{
	double d = 0;
	for (int r = std::max(0, v - 1); r <= std::min<int>(depth_m.rows() - 1, v + 1); ++r)
		for (int c = std::max(0, u - 1); c <= std::min<int>(depth_m.cols() - 1, u + 1); ++c)
			d = std::max(d, 1000.0 * depth_m(r, c));
	return d;
}

bool lineIn(const model::Line3& l, const model::WireFrame& wf)
{
	for (const auto& m : wf.lines)
		if (std::min((m.p1 - l.p1).norm() + (m.p2 - l.p2).norm(),
		             (m.p1 - l.p2).norm() + (m.p2 - l.p1).norm()) < 2 * kSymmetryTol_mm)
			return true;
	return false;
}

bool conicIn(const model::Conic3& c, const model::WireFrame& wf)
{
	const bool circle = c.a - c.b < kSymmetryTol_mm && c.t2 - c.t1 > 2 * M_PI - 1e-6;
	for (const auto& m : wf.conics)
	{
		if ((m.centre - c.centre).norm() > kSymmetryTol_mm) continue;
		if (std::abs(std::abs(m.normal.dot(c.normal)) - 1) > 1e-6) continue;
		if (std::abs(m.a - c.a) > kSymmetryTol_mm || std::abs(m.b - c.b) > kSymmetryTol_mm)
			continue;
		if (circle || std::abs(m.major.dot(c.major)) > 1 - 1e-6) return true;
	}
	return false;
}

bool invariantUnder(const model::WireFrame& wf, double angle_deg)
{
	const Eigen::Matrix3d R = sim::R_aboutZ(angle_deg);
	for (const auto& l : wf.lines)
	{
		model::Line3 t = l;
		t.p1 = R * l.p1, t.p2 = R * l.p2;
		if (!lineIn(t, wf)) return false;
	}
	for (const auto& c : wf.conics)
	{
		model::Conic3 t = c;
		t.centre = R * c.centre, t.normal = R * c.normal, t.major = R * c.major;
		if (!conicIn(t, wf)) return false;
	}
	return true;
}
}  // namespace

double visibleFraction(const model::WireFrame& truth_O, const Eigen::Isometry3d& T_OinL,
                       const cv::Matx33d& K, const mrpt::math::CMatrixFloat& depth_m,
                       double depth_tol_mm)
{
	double total = 0, seen = 0;
	for (const auto& s : model::sampleWireFrame(truth_O, 2))
	{
		total += s.weight_mm;
		const Eigen::Vector3d p = T_OinL * s.p;  // thesis L: x left, y up
		if (p.z() <= 0) continue;
		const int u = static_cast<int>(std::lround(K(0, 0) * -p.x() / p.z() + K(0, 2)));
		const int v = static_cast<int>(std::lround(K(1, 1) * -p.y() / p.z() + K(1, 2)));
		if (u < 0 || v < 0 || u >= depth_m.cols() || v >= depth_m.rows()) continue;
		const double d = farthestDepth_mm(depth_m, u, v);
		if (d <= 0 || p.z() <= d + depth_tol_mm) seen += s.weight_mm;
	}
	return total > 0 ? seen / total : 0;
}

std::vector<double> symmetryAnglesDeg(const model::WireFrame& truth_O)
{
	if (invariantUnder(truth_O, 37) && invariantUnder(truth_O, 113)) return {-1};
	std::vector<double> out = {0};
	for (double a : {90.0, 180.0, 270.0})
		if (invariantUnder(truth_O, a)) out.push_back(a);
	return out;
}

double rotationErrorDeg(const Eigen::Matrix3d& R_true, const Eigen::Matrix3d& R_est,
                        const std::vector<double>& symmetry_deg)
{
	const Eigen::Matrix3d A = R_true.transpose() * R_est;
	auto angleOf = [](double trace)
	{ return std::acos(std::clamp((trace - 1) / 2, -1.0, 1.0)) * 180 / M_PI; };
	if (!symmetry_deg.empty() && symmetry_deg.front() < 0)
	{
		// max over φ of trace(Rz(φ)ᵀ A) = |(A00 + A11, A10 − A01)| + A22
		const double c = A(0, 0) + A(1, 1), s = A(1, 0) - A(0, 1);
		return angleOf(std::hypot(c, s) + A(2, 2));
	}
	double best = 180;
	for (double a : symmetry_deg)
		best = std::min(best, angleOf((sim::R_aboutZ(a).transpose() * A).trace()));
	return best;
}

}  // namespace mrolr::eval
