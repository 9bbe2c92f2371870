#include <mrolr/stereo/Rectifier.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/util/OptionsBinder.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace mrolr::stereo
{
namespace
{
cv::Mat toGrey8(const cv::Mat& img)
{
	cv::Mat g = img;
	if (img.channels() == 3) cv::cvtColor(img, g, cv::COLOR_BGR2GRAY);
	if (img.channels() == 4) cv::cvtColor(img, g, cv::COLOR_BGRA2GRAY);
	if (g.depth() != CV_8U) g.convertTo(g, CV_8U);
	return g;
}

double pointToSegment(const Eigen::Vector3d& p, const LineFit3& l)
{
	const Eigen::Vector3d ab = l.p2 - l.p1;
	const double t = std::clamp((p - l.p1).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
	return (l.p1 + t * ab - p).norm();
}

/** Does an existing line already cover @p l (its ends and middle within tol_mm)? */
bool coveredLine(const std::vector<LineFit3>& lines, const LineFit3& l, double tol)
{
	for (const auto& k : lines)
		if (pointToSegment(l.p1, k) <= tol && pointToSegment(l.p2, k) <= tol &&
		    pointToSegment(0.5 * (l.p1 + l.p2), k) <= tol)
			return true;
	return false;
}

/** Adds the piece features that the 3D strings did not find; returns how many. */
size_t addNewFeatures(StereoScene& scene, const std::vector<LineFit3>& lines,
                      const std::vector<ConicFit3>& conics, double tol)
{
	size_t n = 0;
	for (const auto& l : lines)
		if (!coveredLine(scene.lines, l, tol)) scene.lines.push_back(l), ++n;
	for (const auto& c : conics)
	{
		auto same = [&](const ConicFit3& k)
		{
			return (k.centre - c.centre).norm() <= tol && std::abs(k.a - c.a) <= tol &&
			       std::abs(k.b - c.b) <= tol && std::abs(k.normal.dot(c.normal)) > 0.95;
		};
		auto it = std::find_if(scene.conics.begin(), scene.conics.end(), same);
		if (it == scene.conics.end())
			scene.conics.push_back(c), ++n;
		else if (c.t2 - c.t1 > it->t2 - it->t1)
			*it = c, ++n;  // the longer arc
	}
	return n;
}

/** The parts of the strings inside @p mask (non-zero), at least min_edgels long. */
std::vector<EdgeString> keepInside(const std::vector<EdgeString>& strings, const cv::Mat& mask,
                                   int min_edgels)
{
	std::vector<EdgeString> out;
	const auto flush = [&](EdgeString& run)
	{
		if (static_cast<int>(run.size()) >= min_edgels) out.push_back(std::move(run));
		run.clear();
	};
	for (const auto& s : strings)
	{
		EdgeString run;
		for (const auto& e : s)
		{
			const cv::Point q(cvRound(e.p.x), cvRound(e.p.y));
			if (q.inside(cv::Rect({0, 0}, mask.size())) && mask.at<uchar>(q))
				run.push_back(e);
			else
				flush(run);
		}
		flush(run);
	}
	return out;
}

/** The fitting options of the 2D pieces: the scene's, with segment_min_line_edgels if set. */
FitOptions pieceFitOptions(const SceneOptions& o)
{
	FitOptions f = o.fit;
	if (o.segments.min_line_edgels > 0) f.min_line_edgels = o.segments.min_line_edgels;
	return f;
}

bool continues(const EdgeMatch& prev, const EdgeMatch& m, const FitOptions& o)
{
	return m.string == prev.string && m.edgel - prev.edgel <= o.max_gap_edgels + 1 &&
	       std::abs(m.disparity_px - prev.disparity_px) <= o.max_disparity_jump_px;
}
}  // namespace

namespace
{
using O = SceneOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& sceneOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("min_depth_mm", &O::min_depth_mm, 1, 1e6, kOpt)
	    .number("max_depth_mm", &O::max_depth_mm, 2, 1e7, kOpt)
	    .number("rectify_alpha", [](O& o) -> double& { return o.rectify.alpha; }, 0, 1, kOpt)
	    .number("rectify_size_scale", [](O& o) -> double& { return o.rectify.size_scale; }, 0.25,
	            4, kOpt)
	    .integer("border_margin_px", &O::border_margin_px, 0, 50, kOpt)
	    .flag("horizontal_enabled", [](O& o) -> bool& { return o.horizontal.enabled; }, kOpt)
	    .number("horizontal_max_angle_deg",
	            [](O& o) -> double& { return o.horizontal.max_angle_deg; }, 0, 90, kOpt)
	    .number("horizontal_corner_radius_px",
	            [](O& o) -> double& { return o.horizontal.corner_radius_px; }, 0, 100, kOpt)
	    .number("horizontal_min_right_support",
	            [](O& o) -> double& { return o.horizontal.min_right_support; }, 0, 1, kOpt);
	return b;
}
}  // namespace

SceneOptions::SceneOptions()
{
	// full-image rectification: pieces near the border stay in view (+2.2 points of visible edge
	// length over the eight table views, docs/model.md "Table scenes")
	rectify.alpha = 1;
	rectify.size_scale = 1.25;
	// edgels within 1.5 px of a line or an ellipse belong to it (set on the table views)
	fit.line_tol_px = 1.5;
	fit.conic_tol_px = 1.5;
	// piece stereo (docs/model.md: 32.0 → 50.3 % of the visible edge length). A segment turns
	// between the rectified views by its disparity gradient: the receding top edges of boxes at
	// 0.8 m by up to 50°, so the angle limit is loose and the disparity gradient decides. Pieces
	// of 8–9 edgels (letters' strokes) must match in the grey of both sides (a mark on a surface,
	// not an occluding contour).
	segments.max_angle_diff_deg = 50;
	segments.min_line_edgels = 8;
	segments.both_sides_below_edgels = 10;
	// rims as horizontal circles and rims seen edge-on, when the up direction is known (+1.5 and
	// +1.7 points); a circle's arc within 0.35 px RMS of its edgels (set on the table views)
	circles.enabled = true;
	circles.max_residual_px = 0.35;
	edge_on_rims.enabled = true;
}

void SceneOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                      const std::string& section)
{
	sceneOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "max_depth_mm", max_depth_mm, min_depth_mm + 1, 1e7);
	edges.loadFromConfigFile(cfg, section);
	match.loadFromConfigFile(cfg, section);
	fit.loadFromConfigFile(cfg, section);
	segments.loadFromConfigFile(cfg, section);
	circles.loadFromConfigFile(cfg, section);
	edge_on_rims.loadFromConfigFile(cfg, section);
}

void SceneOptions::dump(std::ostream& out) const
{
	sceneOptionsBinder().dump(out, *this);
	edges.dump(out);
	match.dump(out);
	fit.dump(out);
	segments.dump(out);
	circles.dump(out);
	edge_on_rims.dump(out);
}

std::vector<std::vector<StereoEdgel>> stereoStrings(const std::vector<EdgeMatch>& matches,
                                                    const Rectifier& rect, const FitOptions& o)
{
	std::vector<std::vector<StereoEdgel>> out;
	for (size_t i = 0; i < matches.size(); ++i)
	{
		const EdgeMatch& m = matches[i];
		if (i == 0 || !continues(matches[i - 1], m, o)) out.emplace_back();
		const cv::Point2d xy(m.x_left_px, m.y_px);
		out.back().push_back(
		    {xy, m.disparity_px, rect.pointInLeftCamera(xy.x, xy.y, m.disparity_px)});
	}
	return out;
}

StereoScene reconstructScene(const cv::Mat& left, const cv::Mat& right,
                             const StereoCalibration& calib, const SceneOptions& o,
                             const std::optional<Eigen::Vector3d>& up_L)
{
	const Rectifier rect(calib, o.rectify);
	cv::Mat lr, rr, lm, rm;
	rect.rectify(toGrey8(left), toGrey8(right), lr, rr);
	rect.validMasks(o.border_margin_px, lm, rm);
	const auto ls = keepInside(detectEdgeStrings(lr, o.edges), lm, o.edges.min_string_edgels);
	const auto rs = keepInside(detectEdgeStrings(rr, o.edges), rm, o.edges.min_string_edgels);
	const auto matches = matchEdgeStrings(ls, rs, rect.disparityAtDepth(o.max_depth_mm),
	                                      rect.disparityAtDepth(o.min_depth_mm), o.match);
	StereoScene scene;
	scene.left_strings = ls.size();
	scene.right_strings = rs.size();
	scene.matches = matches.size();
	const auto strings = stereoStrings(matches, rect, o.fit);
	scene.strings3d = strings.size();
	for (const auto& s : strings) segmentString(s, rect, o.fit, scene.lines, scene.conics);
	const auto h = recoverHorizontalLines(ls, rs, matches, rect, rr.size(), o.fit, o.horizontal);
	scene.horizontal_lines = h.size();
	scene.lines.insert(scene.lines.end(), h.begin(), h.end());
	if (o.segments.enabled) addPieceFeatures(ls, rs, lr, rr, matches, rect, o, scene);
	if (o.circles.enabled && up_L) addHorizontalCircles(ls, rs, lr, matches, rect, *up_L, o, scene);
	if (o.edge_on_rims.enabled && up_L)
	{
		const auto rims = edgeOnRims(ls, segmentImageStrings(ls, lr, pieceFitOptions(o)),
		                             scene.lines, scene.conics, *up_L, rect, o.edge_on_rims);
		scene.edge_on_rims = addNewFeatures(scene, {}, rims, o.segments.duplicate_mm);
	}
	return scene;
}

void addPieceFeatures(const std::vector<EdgeString>& ls, const std::vector<EdgeString>& rs,
                      const cv::Mat& lr, const cv::Mat& rr, const std::vector<EdgeMatch>& matches,
                      const Rectifier& rect, const SceneOptions& o, StereoScene& scene)
{
	const FitOptions piece_fit = pieceFitOptions(o);
	const auto lp = segmentImageStrings(ls, lr, piece_fit),
	           rp = segmentImageStrings(rs, rr, piece_fit);
	std::vector<LineFit3> lines;
	std::vector<ConicFit3> conics;
	reconstructPieces({ls, lp, rp, matches, rect.disparityAtDepth(o.max_depth_mm),
	                   rect.disparityAtDepth(o.min_depth_mm), &rs},
	                  rect, o.fit, o.segments, lines, conics);
	scene.piece_features = addNewFeatures(scene, lines, conics, o.segments.duplicate_mm);
}

void addHorizontalCircles(const std::vector<EdgeString>& ls, const std::vector<EdgeString>& rs,
                          const cv::Mat& lr, const std::vector<EdgeMatch>& matches,
                          const Rectifier& rect, const Eigen::Vector3d& up_L, const SceneOptions& o,
                          StereoScene& scene)
{
	const auto lp = segmentImageStrings(ls, lr, pieceFitOptions(o));
	const auto c = horizontalCircles(ls, lp, matches, scene.conics, up_L, rect, o.circles, &rs);
	scene.circle_features = addNewFeatures(scene, {}, c, o.segments.duplicate_mm);
}

}  // namespace mrolr::stereo
