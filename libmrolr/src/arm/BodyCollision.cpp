// Oriented-box overlap (separating axes) and the arm's self-collision pairs.
#include <mrolr/arm/BodyCollision.h>

#include <array>
#include <cmath>
#include <cstdlib>

namespace mrolr::arm
{
namespace
{
/** Half the extent of box @p b projected on unit axis @p n. */
double radiusAlong(const PlacedBox& b, const Eigen::Vector3d& n, double margin_mm)
{
	double r = 0;
	for (int i = 0; i < 3; ++i)
		r += (b.half_mm[i] + margin_mm) * std::abs(b.T_BoxInRef.linear().col(i).dot(n));
	return r;
}

bool separates(const Eigen::Vector3d& axis, const PlacedBox& a, const PlacedBox& b,
               const Eigen::Vector3d& d, double margin_mm)
{
	const double len = axis.norm();
	if (len < 1e-9) return false;  // parallel edges: a face axis already covers this direction
	const Eigen::Vector3d n = axis / len;
	return std::abs(d.dot(n)) > radiusAlong(a, n, margin_mm) + radiusAlong(b, n, 0);
}
}  // namespace

bool boxesOverlap(const PlacedBox& a, const PlacedBox& b, double margin_mm)
{
	const Eigen::Vector3d d = b.T_BoxInRef.translation() - a.T_BoxInRef.translation();
	const Eigen::Matrix3d& A = a.T_BoxInRef.linear();
	const Eigen::Matrix3d& B = b.T_BoxInRef.linear();
	for (int i = 0; i < 3; ++i)
		if (separates(A.col(i), a, b, d, margin_mm) || separates(B.col(i), a, b, d, margin_mm))
			return false;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			if (separates(A.col(i).cross(B.col(j)), a, b, d, margin_mm)) return false;
	return true;
}

std::vector<std::pair<size_t, size_t>> selfCollisionPairs(const std::vector<BodyBox>& body)
{
	// frames joined at a joint: 0–1 (column–carriage), 1–2 and 0–2 (the shoulder on the column),
	// 2–3 (elbow), 3–6 (the wrist: frames 4 and 5 are points); same frame: one rigid part
	auto joined = [](int a, int b)
	{
		if (a > b) std::swap(a, b);
		return a == b || (a <= 1 && b <= 2) || b - a == 1 || (a == 3 && b == 6);
	};
	std::vector<std::pair<size_t, size_t>> out;
	for (size_t i = 0; i < body.size(); ++i)
		for (size_t j = i + 1; j < body.size(); ++j)
			if (!joined(body[i].frame, body[j].frame)) out.emplace_back(i, j);
	return out;
}

std::optional<std::pair<size_t, size_t>> firstSelfContact(
    const std::vector<PlacedBox>& placed, const std::vector<std::pair<size_t, size_t>>& pairs,
    double margin_mm)
{
	for (const auto& [i, j] : pairs)
		if (boxesOverlap(placed.at(i), placed.at(j), margin_mm)) return std::make_pair(i, j);
	return std::nullopt;
}

BodyBox fingerBox(const GraspFeasibilityOptions& grip, double finger_thickness_mm)
{
	const double half_y = grip.gripper_opening_max_mm / 2 + finger_thickness_mm;
	return {6,
	        {-grip.finger_width_mm / 2, -half_y, -grip.finger_length_mm / 2},
	        {grip.finger_width_mm / 2, half_y, grip.finger_length_mm / 2}};
}

std::string bodyBoxName(size_t i)
{
	static const std::array<const char*, 9> names{
	    "column",       "carriage",     "upper arm", "forearm", "wrist stem", "palm",
	    "marker stalk", "marker plate", "fingers"};
	return i < names.size() ? names[i] : "box " + std::to_string(i);
}

}  // namespace mrolr::arm
