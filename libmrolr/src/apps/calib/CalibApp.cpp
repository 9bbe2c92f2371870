#include <mrolr/apps/CalibApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/stereo/CheckerboardCalibration.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <ostream>

namespace mrolr::apps
{
namespace
{
std::vector<std::string> expandGlob(const std::string& pattern, const char* what)
{
	std::vector<cv::String> found;
	try
	{
		cv::glob(pattern, found, false);
	}
	catch (const cv::Exception&)
	{
		found.clear();
	}
	if (found.empty())
		throw util::UsageError(std::string(what) + ": no file matches '" + pattern + "'");
	std::vector<std::string> out(found.begin(), found.end());
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

void CalibApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-calib: stereo calibration from checkerboard image pairs", ' ', "1");
	TCLAP::ValueArg<std::string> left("", "left", "left images (glob, quoted)", true, "", "GLOB",
	                                  cmd);
	TCLAP::ValueArg<std::string> right("", "right", "right images (glob, quoted)", true, "", "GLOB",
	                                   cmd);
	TCLAP::ValueArg<std::string> board("", "board", "inner corners COLSxROWS", true, "9x6", "CxR",
	                                   cmd);
	TCLAP::ValueArg<std::string> square("", "square-mm", "square side (mm)", true, "", "S", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "output .ini", true, "", "FILE", cmd);
	TCLAP::SwitchArg js("", "json", "print the result as JSON", cmd);
	help_shown = !parseTclap(cmd, args);
	if (help_shown) return;
	square_mm = util::parseNumberArg(square.getValue(), "--square-mm");
	board_text = board.getValue();
	out_path = out.getValue();
	json = js.getValue();
	left_files = expandGlob(left.getValue(), "--left");
	right_files = expandGlob(right.getValue(), "--right");
	if (left_files.size() != right_files.size())
		throw util::UsageError("--left matches " + std::to_string(left_files.size()) +
		                       " files but --right matches " + std::to_string(right_files.size()));
}

int CalibApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	stereo::BoardSpec board;
	try
	{
		board = stereo::parseBoardSize(board_text, square_mm);
	}
	catch (const std::invalid_argument& e)
	{
		throw util::UsageError(e.what());
	}
	result = stereo::calibrateStereo(left_files, right_files, board);
	stereo::saveStereoCalibration(result, out_path);
	if (!json)
	{
		result.dump(out);
		out << "written to " << out_path << "\n";
		return util::kExitOk;
	}
	const nlohmann::json j = {{"rms_px", result.rms_px},
	                          {"pairs_used", result.pairs_used},
	                          {"pairs_given", left_files.size()},
	                          {"baseline_mm", result.baseline_mm()},
	                          {"fx_px", result.K_left(0, 0)},
	                          {"fy_px", result.K_left(1, 1)},
	                          {"cx_px", result.K_left(0, 2)},
	                          {"cy_px", result.K_left(1, 2)},
	                          {"out", out_path}};
	out << j.dump(2) << "\n";
	return util::kExitOk;
}

}  // namespace mrolr::apps
