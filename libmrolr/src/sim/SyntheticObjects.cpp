#include <mrolr/recog/WireFrameBuilder.h>
#include <mrolr/sim/SyntheticObjects.h>

#include <array>
#include <cmath>

namespace mrolr::sim
{
namespace
{
using recog::WireFrameBuilder;
using V = Eigen::Vector3d;
using Stroke = std::array<double, 4>;  // u0 v0 u1 v1 in the unit letter box

const std::vector<std::vector<Stroke>>& letterStrokes()
{
	static const std::vector<std::vector<Stroke>> letters = {
	    {{0, 0, 0.5, 1}, {0.5, 1, 1, 0}, {0.25, 0.5, 0.75, 0.5}},        // A
	    {{0, 0, 0, 1}, {0, 1, 1, 1}, {0, 0.5, 0.7, 0.5}, {0, 0, 1, 0}},  // E
	    {{0, 0, 0, 1}, {0, 1, 1, 1}, {0, 0.5, 0.7, 0.5}},                // F
	    {{0, 0, 0, 1}, {1, 0, 1, 1}, {0, 0.5, 1, 0.5}},                  // H
	    {{0, 0, 0, 1}, {0, 0.4, 1, 1}, {0.3, 0.6, 1, 0}},                // K
	    {{0, 1, 1, 1}, {0.5, 1, 0.5, 0}},                                // T
	};
	return letters;
}

/** Draws a letter 30 × 40 mm centred at c in the face spanned by U (right) and V (up). */
void letter(WireFrameBuilder& b, const std::vector<Stroke>& strokes, V c, V U, V Vv)
{
	auto at = [&](double u, double v) { return V(c + (u - 0.5) * 30 * U + (v - 0.5) * 40 * Vv); };
	for (const auto& s : strokes) b.line(at(s[0], s[1]), at(s[2], s[3]));
}

double cupRadius(double z)
{
	return 32 + 8 * z / 95;
}

V onCup(double phi, double z)
{
	return {cupRadius(z) * std::cos(phi), cupRadius(z) * std::sin(phi), z};
}
}  // namespace

model::WireFrame makeAlphabetCube()
{
	WireFrameBuilder b("alphabet_cube");
	b.box({-30, -30, 0}, {30, 30, 60});
	const auto& L = letterStrokes();
	const V X = V::UnitX(), Y = V::UnitY(), Z = V::UnitZ();
	letter(b, L[0], {30, 0, 30}, Y, Z);
	letter(b, L[1], {-30, 0, 30}, -Y, Z);
	letter(b, L[2], {0, 30, 30}, -X, Z);
	letter(b, L[3], {0, -30, 30}, X, Z);
	letter(b, L[4], {0, 0, 60}, X, Y);
	letter(b, L[5], {0, 0, 0}, X, -Y);
	return b.build();
}

model::WireFrame makeCup()
{
	WireFrameBuilder b("cup");
	const V Z = V::UnitZ(), X = V::UnitX(), Y = V::UnitY();
	b.circle({0, 0, 95}, cupRadius(95)).circle({0, 0, 0}, cupRadius(0));
	b.line(onCup(0, 0), onCup(0, 95));
	b.line(onCup(M_PI, 80), {-65, 0, 80}).line(onCup(M_PI, 20), {-65, 0, 20});
	b.arc({-65, 0, 50}, Y, -X, 30, -M_PI / 2, M_PI / 2);
	const double half = 15 * M_PI / 180;
	b.line(onCup(M_PI / 2 - half, 30), onCup(M_PI / 2 - half, 60));
	b.line(onCup(M_PI / 2 + half, 30), onCup(M_PI / 2 + half, 60));
	b.arc({0, 0, 30}, Z, X, cupRadius(30), M_PI / 2 - half, M_PI / 2 + half);
	b.arc({0, 0, 60}, Z, X, cupRadius(60), M_PI / 2 - half, M_PI / 2 + half);
	b.arc({0, 0, 75}, Z, X, cupRadius(75), -1.2, 1.2);
	return b.build();
}

model::WireFrame makeBottle()
{
	WireFrameBuilder b("bottle");
	const V Z = V::UnitZ(), X = V::UnitX();
	b.circle({0, 0, 0}, 35).circle({0, 0, 150}, 35).circle({0, 0, 195}, 14);
	b.circle({0, 0, 205}, 15).circle({0, 0, 225}, 15);
	const double t = 60 * M_PI / 180;
	b.arc({0, 0, 40}, Z, X, 35, -t, t).arc({0, 0, 110}, Z, X, 35, -t, t);
	b.line({35 * std::cos(t), 35 * std::sin(t), 40}, {35 * std::cos(t), 35 * std::sin(t), 110});
	b.line({35 * std::cos(t), -35 * std::sin(t), 40}, {35 * std::cos(t), -35 * std::sin(t), 110});
	b.line({-35, 0, 0}, {-35, 0, 150});
	b.line({0, 35, 150}, {0, 14, 195}).line({0, -35, 150}, {0, -14, 195});
	return b.build();
}

model::WireFrame makeCan()
{
	WireFrameBuilder b("can");
	b.circle({0, 0, 0}, 33).circle({0, 0, 115}, 33).circle({0, 0, 10}, 33).circle({0, 0, 105}, 33);
	b.line({-10, -6, 115}, {18, -6, 115}).line({-10, 6, 115}, {18, 6, 115});
	b.arc({18, 0, 115}, V::UnitZ(), V::UnitX(), 6, -M_PI / 2, M_PI / 2);
	b.line({33, 0, 10}, {33, 0, 105});
	b.line({0, 33, 10}, {0, 33, 50});
	return b.build();
}

model::WireFrame makeStaplerBox()
{
	WireFrameBuilder b("stapler_box");
	b.box({-80, -22.5, 0}, {80, 22.5, 55});
	b.polyline({{-50, -5, 55}, {30, -5, 55}, {30, 5, 55}, {-50, 5, 55}}, true);
	b.circle({55, 0, 55}, 10);
	return b.build();
}

model::WireFrame makeBook()
{
	WireFrameBuilder b("book");
	b.box({-105, -75, 0}, {105, 75, 30});
	b.polyline({{-60, 10, 30}, {60, 10, 30}, {60, 50, 30}, {-60, 50, 30}}, true);
	b.line({-60, -30, 30}, {20, -30, 30});
	return b.build();
}

model::WireFrame makeTeaBox()
{
	WireFrameBuilder b("tea_box");
	b.box({-37.5, -37.5, 0}, {37.5, 37.5, 140});
	b.polyline({{37.5, -25, 40}, {37.5, 25, 40}, {37.5, 25, 110}, {37.5, -25, 110}}, true);
	b.arc({0, 37.5, 100}, V::UnitY(), V::UnitX(), 15, 0, 2 * M_PI);
	return b.build();
}

model::WireFrame makeWedge()
{
	WireFrameBuilder b("wedge");
	b.polyline({{0, -30, 0}, {120, -30, 0}, {120, 30, 0}, {0, 30, 0}}, true);
	b.line({0, -30, 0}, {0, -30, 50}).line({0, 30, 0}, {0, 30, 50}).line({0, -30, 50}, {0, 30, 50});
	b.line({0, -30, 50}, {120, -30, 0}).line({0, 30, 50}, {120, 30, 0});
	auto slope = [](double x, double y) { return V(x, y, 50 - 50 * x / 120); };
	b.line(slope(10, -5), slope(100, -5)).line(slope(10, 5), slope(100, 5));
	return b.build();
}

model::WireFrame makeTapeRoll()
{
	WireFrameBuilder b("tape_roll");
	b.circle({0, 0, 0}, 55).circle({0, 0, 50}, 55).circle({0, 0, 0}, 38).circle({0, 0, 50}, 38);
	b.line({55, 0, 0}, {55, 0, 50});
	b.line({0, -55, 10}, {0, -55, 40});
	b.arc({0, 0, 50}, V::UnitZ(), V::UnitX(), 46, 0.3, 1.8);  // printed label on the top face
	return b.build();
}

model::WireFrame makeBracket()
{
	WireFrameBuilder b("bracket");
	const std::vector<std::pair<double, double>> xz = {{0, 0}, {100, 0}, {100, 8},
	                                                   {8, 8}, {8, 80},  {0, 80}};
	std::vector<V> front, back;
	for (const auto& [x, z] : xz)
	{
		front.push_back({x, 0, z});
		back.push_back({x, 40, z});
	}
	b.polyline(front, true).polyline(back, true);
	for (size_t i = 0; i < front.size(); ++i) b.line(front[i], back[i]);
	b.arc({60, 20, 8}, V::UnitZ(), V::UnitX(), 6, 0, 2 * M_PI);
	b.arc({8, 20, 50}, V::UnitX(), V::UnitY(), 6, 0, 2 * M_PI);
	return b.build();
}

std::vector<model::WireFrame> makeLabObjects()
{
	return {makeAlphabetCube(), makeCup(),    makeBottle(), makeCan(),      makeStaplerBox(),
	        makeBook(),         makeTeaBox(), makeWedge(),  makeTapeRoll(), makeBracket()};
}

}  // namespace mrolr::sim
