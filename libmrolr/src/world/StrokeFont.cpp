#include <mrolr/world/StrokeFont.h>

#include <map>
#include <stdexcept>
#include <string>

namespace mrolr::world
{
namespace
{
using Poly = std::vector<std::vector<double>>;  // polylines as x0 y0 x1 y1 ...

const std::map<char, Poly>& font()
{
	static const std::map<char, Poly> f = {
	    {'A', {{0, 0, 0.3, 1, 0.6, 0}, {0.12, 0.4, 0.48, 0.4}}},
	    {'E', {{0.6, 1, 0, 1, 0, 0, 0.6, 0}, {0, 0.5, 0.45, 0.5}}},
	    {'F', {{0.6, 1, 0, 1, 0, 0}, {0, 0.5, 0.45, 0.5}}},
	    {'H', {{0, 0, 0, 1}, {0.6, 0, 0.6, 1}, {0, 0.5, 0.6, 0.5}}},
	    {'I', {{0.3, 0, 0.3, 1}, {0.1, 0, 0.5, 0}, {0.1, 1, 0.5, 1}}},
	    {'K', {{0, 0, 0, 1}, {0.6, 1, 0, 0.45, 0.6, 0}}},
	    {'L', {{0, 1, 0, 0, 0.6, 0}}},
	    {'M', {{0, 0, 0, 1, 0.3, 0.5, 0.6, 1, 0.6, 0}}},
	    {'N', {{0, 0, 0, 1, 0.6, 0, 0.6, 1}}},
	    {'T', {{0, 1, 0.6, 1}, {0.3, 1, 0.3, 0}}},
	    {'V', {{0, 1, 0.3, 0, 0.6, 1}}},
	    {'W', {{0, 1, 0.15, 0, 0.3, 0.6, 0.45, 0, 0.6, 1}}},
	    {'X', {{0, 0, 0.6, 1}, {0, 1, 0.6, 0}}},
	    {'Y', {{0, 1, 0.3, 0.5, 0.6, 1}, {0.3, 0.5, 0.3, 0}}},
	    {'Z', {{0, 1, 0.6, 1, 0, 0, 0.6, 0}}},
	};
	return f;
}
}  // namespace

bool hasStrokeLetter(char letter)
{
	return font().count(letter) > 0;
}

std::vector<Stroke> strokeLetter(char letter)
{
	const auto it = font().find(letter);
	if (it == font().end())
		throw std::invalid_argument(std::string("no stroke letter '") + letter +
		                            "' (available: A E F H I K L M N T V W X Y Z)");
	std::vector<Stroke> out;
	for (const auto& line : it->second)
		for (size_t i = 2; i + 1 < line.size(); i += 2)
			out.emplace_back(Eigen::Vector2d(line[i - 2], line[i - 1]),
			                 Eigen::Vector2d(line[i], line[i + 1]));
	return out;
}

}  // namespace mrolr::world
