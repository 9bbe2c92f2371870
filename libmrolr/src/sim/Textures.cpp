#include <mrolr/sim/Textures.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
constexpr int kSize = 256;

cv::Mat noisy(int grey, int amplitude, unsigned seed)
{
	cv::Mat m(kSize, kSize, CV_8UC3, cv::Scalar::all(grey));
	cv::Mat n(kSize, kSize, CV_8UC3);
	cv::theRNG().state = seed + 1;
	cv::randu(n, cv::Scalar::all(0), cv::Scalar::all(amplitude));
	cv::GaussianBlur(n, n, cv::Size(5, 5), 1.5);
	return m + n;
}

cv::Mat tiles(int a, int b, int count, unsigned seed)
{
	cv::Mat m = noisy(0, 12, seed);
	const int s = kSize / count;
	for (int i = 0; i < count; ++i)
		for (int j = 0; j < count; ++j)
			m(cv::Rect(i * s, j * s, s, s)) += cv::Scalar::all((i + j) % 2 ? a : b);
	return m;
}

cv::Mat light(unsigned)
{
	cv::Mat m(kSize, kSize, CV_8UC3, cv::Scalar::all(40));
	cv::rectangle(m, cv::Rect(20, 20, kSize - 40, kSize - 40), cv::Scalar::all(250), cv::FILLED);
	for (int x = 20 + (kSize - 40) / 4; x < kSize - 30; x += (kSize - 40) / 4)
		cv::line(m, {x, 20}, {x, kSize - 20}, cv::Scalar::all(90), 6);
	return m;
}

cv::Mat fireSign(unsigned)
{
	cv::Mat m(kSize, kSize, CV_8UC3, cv::Scalar(30, 30, 210));  // BGR red
	cv::rectangle(m, cv::Rect(95, 40, 60, 140), cv::Scalar::all(255), cv::FILLED);
	cv::rectangle(m, cv::Rect(110, 20, 30, 25), cv::Scalar::all(255), cv::FILLED);
	cv::line(m, {140, 30}, {180, 70}, cv::Scalar::all(255), 8);
	cv::putText(m, "FIRE", {48, 235}, cv::FONT_HERSHEY_DUPLEX, 2.0, cv::Scalar::all(255), 4);
	return m;
}

cv::Mat poster(unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_int_distribution<int> pos(0, kSize), rad(12, 50), grey(0, 1);
	cv::Mat m(kSize, kSize, CV_8UC3, cv::Scalar::all(grey(rng) ? 235 : 25));
	for (int i = 0; i < 14; ++i)
	{
		const cv::Scalar c = cv::Scalar::all(grey(rng) ? 245 : 15);
		if (i % 2)
			cv::circle(m, {pos(rng), pos(rng)}, rad(rng), c, cv::FILLED);
		else
			cv::rectangle(m, cv::Rect(pos(rng), pos(rng), 2 * rad(rng), rad(rng)), c, cv::FILLED);
	}
	return m;
}

/** Random grey blobs about 8 texels across over the whole range: dense texture that stereo
 * matching can lock onto (a printed carton, an obstacle). */
cv::Mat speckle(unsigned seed)
{
	cv::Mat small(kSize / 8, kSize / 8, CV_8UC1);
	cv::theRNG().state = seed + 1;
	cv::randu(small, cv::Scalar::all(0), cv::Scalar::all(256));
	cv::Mat big, bgr;
	cv::resize(small, big, cv::Size(kSize, kSize), 0, 0, cv::INTER_CUBIC);
	cv::cvtColor(big, bgr, cv::COLOR_GRAY2BGR);
	return bgr;
}

using Maker = std::function<cv::Mat(unsigned)>;

const std::map<std::string, Maker>& makers()
{
	static const std::map<std::string, Maker> m = {
	    {"wall", [](unsigned s) { return noisy(185, 30, s); }},
	    {"floor", [](unsigned s) { return tiles(95, 125, 8, s); }},
	    {"ceiling", [](unsigned s) { return tiles(205, 215, 4, s); }},
	    {"light", light},
	    {"fire_sign", fireSign},
	    {"poster", poster},
	    {"speckle", speckle},
	    {"checker", [](unsigned s) { return tiles(10, 235, 4 + 2 * int(s % 4), s); }},
	};
	return m;
}

mrpt::img::CImage toCImage(const cv::Mat& bgr)
{
	mrpt::img::CImage img(bgr.clone(), mrpt::img::DEEP_COPY);
	return img;
}
}  // namespace

const std::vector<std::string>& proceduralPatterns()
{
	static const std::vector<std::string> names = []
	{
		std::vector<std::string> n;
		for (const auto& [k, v] : makers()) n.push_back(k);
		return n;
	}();
	return names;
}

mrpt::img::CImage makeProceduralTexture(const std::string& pattern, unsigned seed)
{
	const auto it = makers().find(pattern);
	if (it == makers().end())
		throw std::invalid_argument(
		    "unknown procedural texture '" + pattern +
		    "' (wall, floor, ceiling, light, fire_sign, poster, speckle, checker)");
	return toCImage(it->second(seed));
}

mrpt::img::CImage loadTexture(const std::string& spec, const std::string& base_dir)
{
	const std::string prefix = "procedural:";
	if (spec.rfind(prefix, 0) == 0)
	{
		const std::string rest = spec.substr(prefix.size());
		const auto colon = rest.find(':');
		const unsigned seed =
		    colon == std::string::npos ? 0u : unsigned(std::stoul(rest.substr(colon + 1)));
		return makeProceduralTexture(rest.substr(0, colon), seed);
	}
	std::filesystem::path p(spec);
	if (p.is_relative()) p = std::filesystem::path(base_dir) / p;
	const cv::Mat m = cv::imread(p.string(), cv::IMREAD_COLOR);
	if (m.empty())
		throw std::runtime_error("texture '" + spec + "': cannot read image file " + p.string());
	return toCImage(m);
}

}  // namespace mrolr::sim
