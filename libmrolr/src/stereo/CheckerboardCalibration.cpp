#include <mrolr/stereo/CheckerboardCalibration.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace mrolr::stereo
{
namespace
{
cv::Mat toGrey(const cv::Mat& img)
{
	if (img.channels() == 1) return img;
	cv::Mat g;
	cv::cvtColor(img, g, cv::COLOR_BGR2GRAY);
	return g;
}

/** Detected corners of all usable pairs. */
struct Detections
{
	std::vector<std::vector<cv::Point2f>> left, right;
	cv::Size size;
};

Detections detectAll(const std::vector<cv::Mat>& left, const std::vector<cv::Mat>& right,
                     const BoardSpec& board)
{
	if (left.size() != right.size())
		throw std::runtime_error("calibration needs as many left images (" +
		                         std::to_string(left.size()) + ") as right images (" +
		                         std::to_string(right.size()) + ")");
	Detections d;
	for (size_t i = 0; i < left.size(); ++i)
	{
		if (i == 0) d.size = left[0].size();
		if (left[i].size() != d.size || right[i].size() != d.size)
			throw std::runtime_error("calibration image pair " + std::to_string(i) +
			                         " differs in size");
		auto cl = findBoardCorners(toGrey(left[i]), board);
		auto cr = findBoardCorners(toGrey(right[i]), board);
		if (cl.empty() || cr.empty()) continue;
		d.left.push_back(std::move(cl));
		d.right.push_back(std::move(cr));
	}
	return d;
}

cv::Mat readImage(const std::string& file)
{
	cv::Mat img = cv::imread(file, cv::IMREAD_GRAYSCALE);
	if (img.empty()) throw std::runtime_error("cannot read calibration image '" + file + "'");
	return img;
}

void calibrateOne(const std::vector<std::vector<cv::Point3f>>& obj,
                  const std::vector<std::vector<cv::Point2f>>& img, cv::Size size, cv::Matx33d& K,
                  cv::Vec<double, 5>& D)
{
	cv::Mat Km, Dm;
	std::vector<cv::Mat> rv, tv;
	cv::calibrateCamera(obj, img, size, Km, Dm, rv, tv);
	K = Km;
	for (int i = 0; i < 5; ++i) D[i] = Dm.at<double>(i);
}
}  // namespace

BoardSpec parseBoardSize(const std::string& text, double square_mm)
{
	BoardSpec b;
	char x = 0, extra = 0;
	if (std::sscanf(text.c_str(), "%d%c%d%c", &b.cols, &x, &b.rows, &extra) != 3 ||
	    (x != 'x' && x != 'X') || b.cols < 2 || b.rows < 2)
		throw std::invalid_argument("board size '" + text + "' is not COLSxROWS (e.g. 9x6)");
	if (!(square_mm > 0)) throw std::invalid_argument("square size must be positive (mm)");
	b.square_mm = square_mm;
	return b;
}

std::vector<cv::Point2f> findBoardCorners(const cv::Mat& grey, const BoardSpec& board)
{
	std::vector<cv::Point2f> corners;
	const int flags = cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE;
	if (!cv::findChessboardCorners(grey, {board.cols, board.rows}, corners, flags)) return {};
	const cv::TermCriteria term(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-4);
	cv::cornerSubPix(grey, corners, {11, 11}, {-1, -1}, term);
	return corners;
}

std::vector<cv::Point3f> boardObjectPoints(const BoardSpec& board)
{
	std::vector<cv::Point3f> pts;
	for (int r = 0; r < board.rows; ++r)
		for (int c = 0; c < board.cols; ++c)
			pts.emplace_back(static_cast<float>(c * board.square_mm),
			                 static_cast<float>(r * board.square_mm), 0.f);
	return pts;
}

StereoCalibration calibrateStereo(const std::vector<cv::Mat>& left,
                                  const std::vector<cv::Mat>& right, const BoardSpec& board)
{
	const Detections d = detectAll(left, right, board);
	if (d.left.size() < 2)
		throw std::runtime_error(
		    "the " + std::to_string(board.cols) + "x" + std::to_string(board.rows) +
		    " board was found in both images of only " + std::to_string(d.left.size()) +
		    " pair(s); at least 2 are needed (check --board)");
	const std::vector<std::vector<cv::Point3f>> obj(d.left.size(), boardObjectPoints(board));
	StereoCalibration c;
	c.image_size = d.size;
	c.pairs_used = static_cast<int>(d.left.size());
	calibrateOne(obj, d.left, d.size, c.K_left, c.D_left);
	calibrateOne(obj, d.right, d.size, c.K_right, c.D_right);
	cv::Mat R, T, E, F;
	c.rms_px = cv::stereoCalibrate(obj, d.left, d.right, c.K_left, c.D_left, c.K_right, c.D_right,
	                               d.size, R, T, E, F, cv::CALIB_USE_INTRINSIC_GUESS);
	c.R_RfromL = R;
	c.t_LinR_mm = T;
	return c;
}

StereoCalibration calibrateStereo(const std::vector<std::string>& left_files,
                                  const std::vector<std::string>& right_files,
                                  const BoardSpec& board)
{
	std::vector<cv::Mat> l, r;
	for (const auto& f : left_files) l.push_back(readImage(f));
	for (const auto& f : right_files) r.push_back(readImage(f));
	return calibrateStereo(l, r, board);
}

}  // namespace mrolr::stereo
