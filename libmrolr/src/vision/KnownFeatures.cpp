#include <mrolr/util/Config.h>
#include <mrolr/vision/KnownFeatures.h>

#include <mrpt/config/CConfigFile.h>

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>

namespace mrolr::vision
{
namespace
{
const char* kSection = "known_features";

KnownFeature parseEntry(const mrpt::config::CConfigFileBase& cfg, const std::string& id,
                        const std::filesystem::path& dir)
{
	const auto fields = util::splitFields(util::readString(cfg, kSection, id));
	const std::string where = util::describeKey(cfg, kSection, id);
	KnownFeature f;
	f.id = id;
	if (fields.size() != 4 && fields.size() != 7)
		throw util::ConfigError(where + ": expected 'X Y Z patch.png [sigmaX sigmaY sigmaZ]'");
	for (size_t k = 0; k < fields.size(); ++k)
	{
		double v = 0;
		if (k != 3 && !util::parseDouble(fields[k], v))
			throw util::ConfigError(where + ": '" + fields[k] + "' is not a number");
		if (k < 3) f.p_FinW[int(k)] = v;
		if (k > 3 && !(v >= 0)) throw util::ConfigError(where + ": a sigma must be >= 0");
	}
	const auto png = dir / fields[3];
	f.patch = cv::imread(png.string(), cv::IMREAD_GRAYSCALE);
	if (f.patch.empty()) throw util::ConfigError(where + ": cannot read patch " + png.string());
	if (f.patch.rows != f.patch.cols || f.patch.rows % 2 == 0)
		throw util::ConfigError(where + ": patch " + png.string() + " is not an odd square");
	return f;
}
}  // namespace

std::vector<KnownFeature> loadKnownFeatures(const std::string& path)
{
	const auto cfg = util::openConfigFile(path);
	std::vector<std::string> keys;
	cfg.getAllKeys(kSection, keys);
	std::vector<KnownFeature> out;
	const auto dir = std::filesystem::path(path).parent_path();
	for (const auto& id : keys) out.push_back(parseEntry(cfg, id, dir));
	return out;
}

void saveKnownFeatures(const std::string& path, const std::vector<KnownFeature>& features)
{
	const auto dir = std::filesystem::path(path).parent_path();
	std::filesystem::create_directories(dir / "known_patches");
	std::ofstream out(path);
	if (!out) throw std::runtime_error(path + ": cannot write");
	out << "# Known features (thesis 5.6.2), written by mrolr-slam --acquire-known.\n"
	    << "# id = X Y Z patch.png   (W: x left, y up, z forward, metres; PNG relative to this "
	       "file)\n"
	    << "[" << kSection << "]\n"
	    << std::setprecision(9);
	for (const auto& f : features)
	{
		const std::string rel = "known_patches/" + f.id + ".png";
		if (!cv::imwrite((dir / rel).string(), f.patch))
			throw std::runtime_error((dir / rel).string() + ": cannot write");
		out << f.id << " = " << f.p_FinW.x() << " " << f.p_FinW.y() << " " << f.p_FinW.z() << " "
		    << rel << "\n";
	}
}

}  // namespace mrolr::vision
