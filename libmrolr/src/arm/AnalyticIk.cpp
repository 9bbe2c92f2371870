#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/RtxKinematics.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

// The solve allocates nothing but the result's vectors and formats no text: every quantity below
// is closed form (no rotation matrices built from angles), the turns of a joint are a fixed-size
// list, and a rejected branch is kept as numbers (IkRejection) until reason() is asked for.

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
	return {pw.z(), std::sqrt(pw.x() * pw.x() + pw.y() * pw.y()), std::atan2(pw.y(), pw.x())};
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

/** q2, q3 of the planar pair for one elbow configuration, and cos/sin of q1 + q2 + q3. */
struct ShoulderElbow
{
	double q2 = 0, q3 = 0, c123 = 1, s123 = 0;
};

/** The planar pair for one elbow configuration (@p sign of q3): c3 by the cosine rule, s3 =
 * ±√(1 − c3²), q2 from the wrist's azimuth. */
ShoulderElbow shoulderElbow(const WristCentre& w, const RtxOptions& o, double sign)
{
	const double a2 = o.a2_mm, a3 = o.a3_mm, r = w.radius_mm;
	const double c3 = std::clamp((r * r - a2 * a2 - a3 * a3) / (2 * a2 * a3), -1.0, 1.0);
	const double s3 = sign * std::sqrt(std::max(0.0, 1 - c3 * c3));
	const double q1 = mrpt::DEG2RAD(o.q1_fixed_deg);
	const double q3 = sign * std::acos(c3);
	const double q2 = w.azimuth_rad - std::atan2(a3 * s3, a2 + a3 * c3) - q1;
	const double q123 = q1 + q2 + q3;
	return {q2, q3, std::cos(q123), std::sin(q123)};
}

/** R36 = Rz(q1 + q2 + q3)ᵀ · R06 without forming the rotation. */
Eigen::Matrix3d wristRotation(const Eigen::Matrix3d& R06, double c, double s)
{
	Eigen::Matrix3d R36;
	R36.row(0) = c * R06.row(0) + s * R06.row(1);
	R36.row(1) = -s * R06.row(0) + c * R06.row(1);
	R36.row(2) = R06.row(2);
	return R36;
}

/** Wrist angles q4, q5, q6 for R36 = Rz(q4)·Rx(90°)·Rz(q5)·Rx(90°)·Rz(q6); q5 >= 0 unless
 * @p flipped. With A = Rz(q4)·Rx(90°)·Rz(q5)·Rx(90°) = [c4c5 s4 c4s5; s4c5 −c4 s4s5; s5 0 −c5],
 * Rz(q6) = Aᵀ·R36 gives q6 = atan2(s4·r00 − c4·r10, c4c5·r00 + s4c5·r10 + s5·r20). At q5 = 0 or
 * 180° only q4 ∓ q6 matters: q4 = 0 is chosen. */
std::array<double, 3> wristAngles(const Eigen::Matrix3d& R36, bool flipped)
{
	const Eigen::Vector3d a = R36.col(2);  // (c4 s5, s4 s5, −c5)
	const double s5_abs = std::sqrt(a.x() * a.x() + a.y() * a.y());
	const double s5 = flipped ? -s5_abs : s5_abs;
	const double q5 = std::atan2(s5, -a.z());
	const bool regular = s5_abs > 1e-12;
	const double q4 = regular ? std::atan2(a.y() / s5, a.x() / s5) : 0.0;
	const double c4 = regular ? a.x() / s5 : 1.0, s4 = regular ? a.y() / s5 : 0.0;
	const double n5 = std::sqrt(s5 * s5 + a.z() * a.z());
	const double c5 = -a.z() / n5, sn5 = s5 / n5;
	const double y = s4 * R36(0, 0) - c4 * R36(1, 0);
	const double x = c4 * c5 * R36(0, 0) + s4 * c5 * R36(1, 0) + sn5 * R36(2, 0);
	return {q4, q5, std::atan2(y, x)};
}

/** The flipped wrist (q5 < 0) of a regular one: (q4 + π, −q5, q6 + π) gives the same R36, since
 * c4, s4 and s5 change sign and c5 does not. At q5 = 0 or 180° it is solved afresh. */
std::array<double, 3> flippedWrist(const std::array<double, 3>& normal, const Eigen::Matrix3d& R36)
{
	const Eigen::Vector3d a = R36.col(2);
	if (a.x() * a.x() + a.y() * a.y() <= 1e-24) return wristAngles(R36, true);
	return {normal[0] + M_PI, -normal[1], normal[2] + M_PI};
}

/** mrpt::math::wrapToPi into [−π, π), without its fmod for an angle within one turn of it. */
double wrapToPi(double a)
{
	if (a >= -M_PI && a < M_PI) return a;
	if (a >= M_PI && a < 3 * M_PI) return a - 2 * M_PI;
	if (a < -M_PI && a >= -3 * M_PI) return a + 2 * M_PI;
	return mrpt::math::wrapToPi(a);
}

/** Up to N values, without the heap. */
template <class T, size_t N>
struct SmallList
{
	std::array<T, N> v{};
	size_t n = 0;
	void push(const T& x) { v[n++] = x; }
	bool empty() const { return n == 0; }
	const T* begin() const { return v.data(); }
	const T* end() const { return v.data() + n; }
};
using Turns = SmallList<double, 3>;                       ///< the turns of one joint
using WristTurns = SmallList<std::pair<double, double>, 9>;  ///< (q5, q6) pairs

bool inLimit(double count, const CountRange& r)
{
	return count >= r.min - 1e-9 && count <= r.max + 1e-9;
}

/** a + 2πk, k ∈ {−1, 0, 1}, with a normalised to [−π, π), whose count lies within @p r. */
Turns turnsWithin(double a, double deg_per_count, const CountRange& r)
{
	Turns out;
	const double base = wrapToPi(a);
	for (int k = -1; k <= 1; ++k)
	{
		const double v = base + 2 * M_PI * k;
		if (inLimit(mrpt::RAD2DEG(v) / deg_per_count, r)) out.push(v);
	}
	return out;
}

/** (q5, q6) pairs, each turned by 0 or ±360°, within both differential wrist motors' limits. */
WristTurns wristTurnsWithin(double q5, double q6, const RtxOptions& o)
{
	WristTurns out;
	const double b5 = wrapToPi(q5), b6 = wrapToPi(q6);
	for (int k5 = -1; k5 <= 1; ++k5)
		for (int k6 = -1; k6 <= 1; ++k6)
		{
			const double a5 = b5 + 2 * M_PI * k5, a6 = b6 + 2 * M_PI * k6;
			const auto [w1, w2] = wristCounts(a5, a6, o);
			if (inLimit(w1, o.limit(Motor::Wrist1)) && inLimit(w2, o.limit(Motor::Wrist2)))
				out.push({a5, a6});
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

void addSolution(const IkSolution& s, IkResult& res)
{
	for (const auto& t : res.solutions)
		if (sameJoints(t.joints, s.joints)) return;
	if (res.solutions.empty()) res.solutions.reserve(8);
	res.solutions.push_back(s);
}

/** Adds every turn of @p j within the limits, or why none is. */
void addWithinLimits(const RtxJoints& j, const RtxOptions& o, IkSolution proto, IkResult& res)
{
	const Turns q2s = turnsWithin(j.q(2), o.shoulder_deg_per_count, o.limit(Motor::Shoulder));
	const Turns q3s = turnsWithin(j.q(3), o.elbow_deg_per_count, o.limit(Motor::Elbow));
	const Turns q4s = turnsWithin(j.q(4), o.yaw_deg_per_count, o.limit(Motor::Yaw));
	const WristTurns w56 = wristTurnsWithin(j.q(5), j.q(6), o);
	const size_t before = res.solutions.size();
	for (double q2 : q2s)
		for (double q3 : q3s)
			for (double q4 : q4s)
				for (const auto& [q5, q6] : w56)
				{
					proto.joints = j;
					proto.joints.q_rad = {j.q(1), q2, q3, q4, q5, q6};
					proto.counts = jointsToCounts(proto.joints, o);
					addSolution(proto, res);
				}
	if (res.solutions.size() > before || !(q2s.empty() || q3s.empty() || q4s.empty() || w56.empty()))
		return;
	RtxJoints wrapped = j;
	for (size_t i = 1; i < 6; ++i) wrapped.q_rad[i] = mrpt::math::wrapToPi(j.q_rad[i]);
	const MotorCounts c = jointsToCounts(wrapped, o);
	const int m = firstViolatedMotor(c, o);
	IkRejection r;
	r.elbow_left = proto.elbow_left;
	r.wrist_flipped = proto.wrist_flipped;
	if (m >= 0)
	{
		r.motor = static_cast<Motor>(m);
		r.count = c[static_cast<size_t>(m)];
		r.limit = o.limits[m];
	}
	else  // every wrapped count is within its limit, yet no turn is: cannot happen, said plainly
		r.pose_reason = branchName(r.elbow_left, r.wrist_flipped) + ": no turn within the limits";
	if (res.rejected.empty()) res.rejected.reserve(4);
	res.rejected.push_back(std::move(r));
}

IkRejection poseRejection(std::string why)
{
	IkRejection r;
	r.pose_reason = std::move(why);
	return r;
}
}  // namespace

std::string IkRejection::text() const
{
	if (!pose_reason.empty()) return pose_reason;
	return branchName(elbow_left, wrist_flipped) + ": " + describeViolation(motor, count, limit);
}

std::string IkResult::reason() const
{
	if (!solutions.empty()) return {};
	std::string out;
	for (const auto& r : rejected) out += (out.empty() ? "" : "; ") + r.text();
	return out.empty() ? "no solution" : out;
}

AnalyticIk::AnalyticIk(const RtxOptions& options) : o_(options) {}

IkResult AnalyticIk::solve(const Eigen::Isometry3d& T06) const
{
	IkResult res;
	if (!T06.matrix().allFinite())
	{
		res.rejected.push_back(poseRejection("the requested pose has a non-finite element"));
		return res;
	}
	const WristCentre w = wristCentre(T06, o_.d6_mm);
	std::string violation = wristCentreViolation(w, o_);
	if (!violation.empty())
	{
		res.rejected.push_back(poseRejection(std::move(violation)));
		return res;
	}
	const double q1 = mrpt::DEG2RAD(o_.q1_fixed_deg);
	for (double elbow_sign : {-1.0, 1.0})
	{
		const ShoulderElbow se = shoulderElbow(w, o_, elbow_sign);
		const Eigen::Matrix3d R36 = wristRotation(T06.linear(), se.c123, se.s123);
		const std::array<double, 3> normal = wristAngles(R36, false);
		for (bool flipped : {false, true})
		{
			const auto [q4, q5, q6] = flipped ? flippedWrist(normal, R36) : normal;
			RtxJoints j;
			j.d1_mm = w.d1_mm;
			j.q_rad = {q1, se.q2, se.q3, q4, q5, q6};
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
