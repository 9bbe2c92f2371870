#include <mrolr/stereo/StereoCalibration.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace mrolr::stereo
{
namespace
{
template <typename M>
void readInto(M& m, const mrpt::config::CConfigFileBase& cfg, const std::string& sec,
              const std::string& key)
{
	const auto v = util::readDoubles(cfg, sec, key, static_cast<size_t>(M::rows * M::cols));
	for (int i = 0; i < M::rows * M::cols; ++i) m.val[i] = v[static_cast<size_t>(i)];
}

template <typename M>
std::string joined(const M& m)
{
	std::ostringstream ss;
	ss << std::setprecision(std::numeric_limits<double>::max_digits10);
	for (int i = 0; i < M::rows * M::cols; ++i) ss << (i ? " " : "") << m.val[i];
	return ss.str();
}

void checkRotation(const cv::Matx33d& R, const mrpt::config::CConfigFileBase& cfg,
                   const std::string& sec)
{
	const double err = cv::norm(R * R.t() - cv::Matx33d::eye());
	if (err > 1e-6 || cv::determinant(R) < 0)
		throw util::ConfigError(util::describeKey(cfg, sec, "R_RfromL") +
		                        ": not a rotation matrix (|R Rt - I| = " + std::to_string(err) +
		                        ")");
}
}  // namespace

void StereoCalibration::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& section)
{
	const long w = util::readInt(cfg, section, "image_width_px");
	const long h = util::readInt(cfg, section, "image_height_px");
	util::requireInRange(cfg, section, "image_width_px", static_cast<double>(w), 1, 1e5);
	util::requireInRange(cfg, section, "image_height_px", static_cast<double>(h), 1, 1e5);
	image_size = cv::Size(static_cast<int>(w), static_cast<int>(h));
	readInto(K_left, cfg, section, "K_left_px");
	readInto(K_right, cfg, section, "K_right_px");
	readInto(D_left, cfg, section, "dist_left");
	readInto(D_right, cfg, section, "dist_right");
	readInto(R_RfromL, cfg, section, "R_RfromL");
	readInto(t_LinR_mm, cfg, section, "t_LinR_mm");
	checkRotation(R_RfromL, cfg, section);
	util::requireInRange(cfg, section, "K_left_px", K_left(0, 0), 1e-3, 1e7);
	util::requireInRange(cfg, section, "K_right_px", K_right(0, 0), 1e-3, 1e7);
	rms_px = util::readDouble(cfg, section, "rms_px", 0.0);
	pairs_used = static_cast<int>(util::readInt(cfg, section, "pairs_used", 0));
}

void StereoCalibration::saveToConfigFile(mrpt::config::CConfigFileBase& cfg,
                                         const std::string& section) const
{
	cfg.write(section, "image_width_px", image_size.width);
	cfg.write(section, "image_height_px", image_size.height);
	cfg.write(section, "K_left_px", joined(K_left));
	cfg.write(section, "K_right_px", joined(K_right));
	cfg.write(section, "dist_left", joined(D_left));
	cfg.write(section, "dist_right", joined(D_right));
	cfg.write(section, "R_RfromL", joined(R_RfromL));
	cfg.write(section, "t_LinR_mm", joined(t_LinR_mm));
	cfg.write(section, "rms_px", joined(cv::Vec<double, 1>(rms_px)));
	cfg.write(section, "pairs_used", pairs_used);
}

void StereoCalibration::dump(std::ostream& out) const
{
	out << "image " << image_size.width << "x" << image_size.height << " px, fx " << K_left(0, 0)
	    << " px, fy " << K_left(1, 1) << " px, baseline " << baseline_mm() << " mm, RMS " << rms_px
	    << " px over " << pairs_used << " pairs\n";
}

StereoCalibration loadStereoCalibration(const std::string& ini_path)
{
	if (!std::filesystem::exists(ini_path))
		throw std::runtime_error("calibration file '" + ini_path + "' does not exist");
	mrpt::config::CConfigFile cfg(ini_path);
	StereoCalibration c;
	c.loadFromConfigFile(cfg, "stereo_calib");
	return c;
}

void saveStereoCalibration(const StereoCalibration& calib, const std::string& ini_path)
{
	{
		std::ofstream probe(ini_path);
		if (!probe) throw std::runtime_error("cannot write calibration file '" + ini_path + "'");
	}
	mrpt::config::CConfigFile cfg(ini_path);
	calib.saveToConfigFile(cfg, "stereo_calib");
	cfg.writeNow();
}

}  // namespace mrolr::stereo
