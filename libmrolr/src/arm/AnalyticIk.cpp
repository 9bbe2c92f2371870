#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/RtxKinematics.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mrolr::arm
{
namespace
{
struct WristCentre
{
	double d1_mm = 0, radius_mm = 0, azimuth_rad = 0;
};

WristCentre wristCentre(const Eigen::Isometry3d& T06, double d6_mm)
{
	const Eigen::Vector3d pw = T06.translation() - d6_mm * T06.linear().col(2);
	return {pw.z(), std::hypot(pw.x(), pw.y()), std::atan2(pw.y(), pw.x())};
}

std::string describe(const std::string& what, double value, double lo, double hi, const char* unit)
{
	std::ostringstream s;
	s << what << " " << value << " " << unit << " outside limit [" << lo << ", " << hi << "] "
	  << unit;
	return s.str();
}

/** Reason the wrist centre cannot be reached (column range or wrist radius), or "". */
std::string wristCentreViolation(const WristCentre& w, const RtxOptions& o)
{
	const double lo = o.d1_top_mm + o.limit(Motor::Column).min * o.column_mm_per_count;
	const double hi = o.d1_top_mm + o.limit(Motor::Column).max * o.column_mm_per_count;
	if (w.d1_mm < lo - 1e-9 || w.d1_mm > hi + 1e-9)
		return describe("column height d1 of the wrist centre", w.d1_mm, lo, hi, "mm");
	const double reach = std::min(o.wrist_radius_max_mm, o.a2_mm + o.a3_mm);
	const double inner = std::abs(o.a2_mm - o.a3_mm);
	if (w.radius_mm > reach + 1e-9 || w.radius_mm < inner - 1e-9)
		return describe("wrist radius", w.radius_mm, inner, reach, "mm");
	return {};
}

/** (q2, q3) of the planar pair for one elbow configuration (sign of q3). */
std::pair<double, double> shoulderElbow(const WristCentre& w, const RtxOptions& o, double sign)
{
	const double a2 = o.a2_mm, a3 = o.a3_mm, r = w.radius_mm;
	const double c3 = std::clamp((r * r - a2 * a2 - a3 * a3) / (2 * a2 * a3), -1.0, 1.0);
	const double q3 = sign * std::acos(c3);
	const double q2 = w.azimuth_rad - std::atan2(a3 * std::sin(q3), a2 + a3 * std::cos(q3));
	return {q2 - mrpt::DEG2RAD(o.q1_fixed_deg), q3};
}

/** Wrist angles q4, q5, q6 for R36 = Rz(q4)·Rx(90°)·Rz(q5)·Rx(90°)·Rz(q6); q5 >= 0 unless
 * @p flipped. At q5 = 0 or 180° only q4 ∓ q6 matters: q4 = 0 is chosen. */
std::array<double, 3> wristAngles(const Eigen::Matrix3d& R36, bool flipped)
{
	const Eigen::Vector3d a = R36.col(2);  // (c4 s5, s4 s5, −c5)
	const double s5_abs = std::hypot(a.x(), a.y());
	const double s5 = flipped ? -s5_abs : s5_abs;
	const double q5 = std::atan2(s5, -a.z());
	const double q4 = s5_abs > 1e-12 ? std::atan2(a.y() / s5, a.x() / s5) : 0.0;
	// q6 from what is left: Rz(q6) = (Rz(q4) Rx(90) Rz(q5) Rx(90))ᵀ R36
	const Eigen::Matrix3d Rx90 = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).matrix();
	const Eigen::Matrix3d R35 = Eigen::AngleAxisd(q4, Eigen::Vector3d::UnitZ()).matrix() * Rx90 *
	                            Eigen::AngleAxisd(q5, Eigen::Vector3d::UnitZ()).matrix() * Rx90;
	const Eigen::Matrix3d R56 = R35.transpose() * R36;
	return {q4, q5, std::atan2(R56(1, 0), R56(0, 0))};
}

/** a + 2πk, k ∈ {−1, 0, 1}, with a normalised to (−π, π], whose count lies within @p r. */
std::vector<double> turnsWithin(double a, double deg_per_count, const CountRange& r)
{
	std::vector<double> out;
	const double base = mrpt::math::wrapToPi(a);
	for (int k = -1; k <= 1; ++k)
	{
		const double v = base + 2 * M_PI * k;
		const double c = mrpt::RAD2DEG(v) / deg_per_count;
		if (c >= r.min - 1e-9 && c <= r.max + 1e-9) out.push_back(v);
	}
	return out;
}

/** (q5, q6) pairs, each turned by 0 or ±360°, within both differential wrist motors' limits. */
std::vector<std::pair<double, double>> wristTurnsWithin(double q5, double q6, const RtxOptions& o)
{
	std::vector<std::pair<double, double>> out;
	for (double a5 : turnsWithin(q5, 1.0, {-1e9, 1e9}))
		for (double a6 : turnsWithin(q6, 1.0, {-1e9, 1e9}))
		{
			RtxJoints j;
			j.q_rad[4] = a5;
			j.q_rad[5] = a6;
			const MotorCounts c = jointsToCounts(j, o);
			const auto in = [&](Motor m)
			{
				const auto& r = o.limit(m);
				const double v = c[static_cast<size_t>(m)];
				return v >= r.min - 1e-9 && v <= r.max + 1e-9;
			};
			if (in(Motor::Wrist1) && in(Motor::Wrist2)) out.emplace_back(a5, a6);
		}
	return out;
}

std::string branchName(bool elbow_left, bool flipped)
{
	return std::string(elbow_left ? "elbow left" : "elbow right") +
	       (flipped ? ", wrist flipped" : ", wrist normal");
}

bool sameJoints(const RtxJoints& a, const RtxJoints& b)
{
	if (std::abs(a.d1_mm - b.d1_mm) > 1e-9) return false;
	for (size_t i = 0; i < 6; ++i)
		if (std::abs(a.q_rad[i] - b.q_rad[i]) > 1e-9) return false;
	return true;
}

/** Adds every turn of @p j within the limits, or the reason none is. */
void addWithinLimits(const RtxJoints& j, const RtxOptions& o, IkSolution proto, IkResult& res)
{
	const auto q2s = turnsWithin(j.q(2), o.shoulder_deg_per_count, o.limit(Motor::Shoulder));
	const auto q3s = turnsWithin(j.q(3), o.elbow_deg_per_count, o.limit(Motor::Elbow));
	const auto q4s = turnsWithin(j.q(4), o.yaw_deg_per_count, o.limit(Motor::Yaw));
	const auto w56 = wristTurnsWithin(j.q(5), j.q(6), o);
	const size_t before = res.solutions.size();
	for (double q2 : q2s)
		for (double q3 : q3s)
			for (double q4 : q4s)
				for (const auto& [q5, q6] : w56)
				{
					proto.joints = j;
					proto.joints.q_rad = {j.q(1), q2, q3, q4, q5, q6};
					proto.counts = jointsToCounts(proto.joints, o);
					bool dup = false;
					for (const auto& s : res.solutions)
						dup = dup || sameJoints(s.joints, proto.joints);
					if (!dup) res.solutions.push_back(proto);
				}
	if (res.solutions.size() > before ||
	    !(q2s.empty() || q3s.empty() || q4s.empty() || w56.empty()))
		return;
	RtxJoints wrapped = j;
	for (size_t i = 1; i < 6; ++i) wrapped.q_rad[i] = mrpt::math::wrapToPi(j.q_rad[i]);
	res.rejected.push_back(branchName(proto.elbow_left, proto.wrist_flipped) + ": " +
	                       limitViolation(jointsToCounts(wrapped, o), o));
}
}  // namespace

std::string IkResult::reason() const
{
	if (!solutions.empty()) return {};
	std::string out;
	for (const auto& r : rejected) out += (out.empty() ? "" : "; ") + r;
	return out.empty() ? "no solution" : out;
}

AnalyticIk::AnalyticIk(const RtxOptions& options) : o_(options) {}

IkResult AnalyticIk::solve(const Eigen::Isometry3d& T06) const
{
	IkResult res;
	if (!T06.matrix().allFinite())
	{
		res.rejected.push_back("the requested pose has a non-finite element");
		return res;
	}
	const WristCentre w = wristCentre(T06, o_.d6_mm);
	const std::string violation = wristCentreViolation(w, o_);
	if (!violation.empty())
	{
		res.rejected.push_back(violation);
		return res;
	}
	const double q1 = mrpt::DEG2RAD(o_.q1_fixed_deg);
	for (double elbow_sign : {-1.0, 1.0})
	{
		const auto [q2, q3] = shoulderElbow(w, o_, elbow_sign);
		const Eigen::Matrix3d R03 =
		    Eigen::AngleAxisd(q1 + q2 + q3, Eigen::Vector3d::UnitZ()).matrix();
		const Eigen::Matrix3d R36 = R03.transpose() * T06.linear();
		for (bool flipped : {false, true})
		{
			const auto [q4, q5, q6] = wristAngles(R36, flipped);
			RtxJoints j;
			j.d1_mm = w.d1_mm;
			j.q_rad = {q1, q2, q3, q4, q5, q6};
			IkSolution proto;
			proto.elbow_left = elbow_sign < 0;
			proto.wrist_flipped = flipped;
			addWithinLimits(j, o_, proto, res);
		}
	}
	return res;
}

std::vector<IkSolution> AnalyticIk::solveAll(const Eigen::Isometry3d& T06) const
{
	IkResult r = solve(T06);
	if (r.solutions.empty()) throw UnreachableError("unreachable pose: " + r.reason());
	return std::move(r.solutions);
}

}  // namespace mrolr::arm
