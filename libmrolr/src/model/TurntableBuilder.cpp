#include <mrolr/model/SceneModel.h>
#include <mrolr/model/TurntableBuilder.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/stereo/StereoCalibration.h>
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/config/CConfigFile.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <stdexcept>

namespace mrolr::model
{
namespace
{
std::string inDir(const std::string& dir, const std::string& file)
{
	return (std::filesystem::path(dir) / file).string();
}

Eigen::Isometry3d readPose(const mrpt::config::CConfigFileBase& cfg, const std::string& sec)
{
	const auto r = util::readDoubles(cfg, sec, "R_TfromL", 9);
	const auto t = util::readDoubles(cfg, sec, "t_LinT_mm", 3);
	Eigen::Matrix3d R;
	R << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
	if ((R * R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-6 || R.determinant() < 0)
		throw util::ConfigError(util::describeKey(cfg, sec, "R_TfromL") +
		                        ": not a rotation matrix");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = R;
	T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
	return T;
}

cv::Mat readImage(const std::string& path)
{
	cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
	if (img.empty()) throw std::runtime_error("cannot read turntable image '" + path + "'");
	return img;
}

bool insideObject(const Eigen::Vector3d& p, const TurntableOptions& o)
{
	return p.head<2>().norm() <= o.keep_radius_mm && p.z() >= o.min_height_mm &&
	       p.z() <= o.max_height_mm;
}
}  // namespace

TurntableSet loadTurntableSet(const std::string& dir)
{
	const std::string ini = inDir(dir, "turntable.ini");
	if (!std::filesystem::exists(ini))
		throw std::runtime_error("no turntable.ini in '" + dir + "'");
	mrpt::config::CConfigFile cfg(ini);
	TurntableSet s;
	s.object = util::readString(cfg, "turntable", "object");
	s.calib_path = inDir(dir, util::readString(cfg, "turntable", "calib"));
	if (util::hasKey(cfg, "turntable", "truth"))
		s.truth_path = inDir(dir, util::readString(cfg, "turntable", "truth"));
	s.T_LinT_mm = readPose(cfg, "turntable");
	const long n = util::readInt(cfg, "turntable", "views");
	util::requireInRange(cfg, "turntable", "views", static_cast<double>(n), 1, 1000);
	for (long i = 0; i < n; ++i)
	{
		const std::string sec = "view_" + std::to_string(i);
		s.views.push_back({inDir(dir, util::readString(cfg, sec, "left")),
		                   inDir(dir, util::readString(cfg, sec, "right")),
		                   util::readDouble(cfg, sec, "angle_deg")});
	}
	return s;
}

namespace
{
using O = TurntableOptions;
constexpr auto kOpt = util::Presence::Optional;  // [turntable]: every key of config/model.ini

const util::OptionsBinder<O>& turntableOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<O>()
	        .number("keep_radius_mm", &O::keep_radius_mm, 1, 1e5, kOpt)
	        .number("min_height_mm", &O::min_height_mm, -1e6, 1e6, kOpt)
	        .number("max_height_mm", &O::max_height_mm, -1e6, 1e6, kOpt)
	        // also read by ViewSupportOptions (same key), whose range this is
	        .integer("min_views", &O::min_views, 1, 1000, kOpt)
	        .number("merge_max_distance_mm",
	                [](O& o) -> double& { return o.merge.max_distance_mm; }, 0, 1e6, kOpt)
	        .number("merge_max_angle_deg", [](O& o) -> double& { return o.merge.max_angle_deg; },
	                0, 90, kOpt)
	        .number("merge_max_gap_mm", [](O& o) -> double& { return o.merge.max_gap_mm; }, 0,
	                1e6, kOpt)
	        .number("merge_max_centre_mm", [](O& o) -> double& { return o.merge.max_centre_mm; },
	                0, 1e6, kOpt)
	        .number("merge_max_radius_diff_mm",
	                [](O& o) -> double& { return o.merge.max_radius_diff_mm; }, 0, 1e6, kOpt)
	        .number("rim_image_gradient", [](O& o) -> double& { return o.rim_images.min_gradient; },
	                0, 1e4, kOpt)
	        .number("rim_image_min_fraction",
	                [](O& o) -> double& { return o.rim_images.min_fraction; }, 0, 1, kOpt)
	        .number("rim_image_max_tilt_deg",
	                [](O& o) -> double& { return o.rim_images.max_tilt_deg; }, 0, 90, kOpt);
	return b;
}
}  // namespace

TurntableOptions::TurntableOptions()
{
	// 20 → 15° with the luminance renders: the cube's top letter K gave strokes 20° off in single
	// views that the true strokes of other views supported (cube 6 → 1 false segments)
	support.max_tangent_deg = 15;
	// a rim's arc is completed piece by piece where a facing view's image shows an edge
	// (Sobel |∇I| ≥ 8 grey levels/px, the support check's threshold)
	rim_images.min_gradient = 8;
}

void TurntableOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& section)
{
	turntableOptionsBinder().load(cfg, section, *this);
	support.loadFromConfigFile(cfg, section);
	rims.max_radius_mm = keep_radius_mm;
	rims.loadFromConfigFile(cfg, section);
	rim_chords.min_radius_mm = rims.min_radius_mm;
	rim_chords.max_radius_mm = rims.max_radius_mm;
	rim_chords.loadFromConfigFile(cfg, section);
}

void cropToObject(WireFrame& wf, const TurntableOptions& o)
{
	auto outside = [&](const std::vector<FeatureSample>& s)
	{ return std::any_of(s.begin(), s.end(), [&](auto& q) { return !insideObject(q.p, o); }); };
	wf.lines.erase(std::remove_if(wf.lines.begin(), wf.lines.end(),
	                              [&](const Line3& l) { return outside(sampleLine(l, 5.0, 0)); }),
	               wf.lines.end());
	wf.conics.erase(
	    std::remove_if(wf.conics.begin(), wf.conics.end(),
	                   [&](const Conic3& c) { return outside(sampleConic(c, 5.0, 0)); }),
	    wf.conics.end());
}

WireFrame viewInObjectFrame(const stereo::StereoScene& scene, const Eigen::Isometry3d& T_LinT_mm,
                            double angle_deg, const TurntableOptions& o)
{
	const Eigen::Isometry3d T_TinO(
	    Eigen::AngleAxisd(-angle_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
	WireFrame wf =
	    transformWireFrame(sceneToWireFrame(scene), T_TinO * T_LinT_mm, WireFrameFrame::Object);
	cropToObject(wf, o);
	return wf;
}

namespace
{
template <typename T>
int viewsSupporting(const T& f, const std::vector<WireFrame>& views, const MergeOptions& o,
                    const std::vector<T>& (*features)(const WireFrame&))
{
	int n = 0;
	for (const auto& v : views)
	{
		const auto& list = features(v);
		n +=
		    std::any_of(list.begin(), list.end(), [&](const T& g) { return isDuplicate(f, g, o); });
	}
	return n;
}

const std::vector<Line3>& linesOf(const WireFrame& w)
{
	return w.lines;
}
const std::vector<Conic3>& conicsOf(const WireFrame& w)
{
	return w.conics;
}
}  // namespace

size_t dropUnsupported(WireFrame& merged, const std::vector<WireFrame>& views, int min_views,
                       const MergeOptions& o)
{
	const size_t before = featureCount(merged);
	merged.lines.erase(std::remove_if(merged.lines.begin(), merged.lines.end(),
	                                  [&](const Line3& l) {
		                                  return viewsSupporting(l, views, o, linesOf) < min_views;
	                                  }),
	                   merged.lines.end());
	merged.conics.erase(
	    std::remove_if(merged.conics.begin(), merged.conics.end(),
	                   [&](const Conic3& c)
	                   { return viewsSupporting(c, views, o, conicsOf) < min_views; }),
	    merged.conics.end());
	return before - featureCount(merged);
}

void renumber(WireFrame& wf)
{
	int id = 1;
	for (auto& l : wf.lines) l.id = id++;
	for (auto& c : wf.conics) c.id = id++;
	wf.cliques.clear();
}

stereo::SceneOptions turntableSceneOptions(const stereo::SceneOptions& scene_options)
{
	stereo::SceneOptions so = scene_options;
	so.segments.corner_lines = false;
	return so;
}

WireFrame buildFromTurntable(const TurntableSet& set, const stereo::SceneOptions& scene_options,
                             const TurntableOptions& o)
{
	const stereo::SceneOptions so = turntableSceneOptions(scene_options);
	const stereo::StereoCalibration calib = stereo::loadStereoCalibration(set.calib_path);
	std::vector<WireFrame> views;
	std::vector<double> angles_deg;
	std::vector<ViewEdges> edges;
	for (const auto& v : set.views)
	{
		const cv::Mat left = readImage(v.left_png);
		const auto scene = stereo::reconstructScene(left, readImage(v.right_png), calib, so);
		views.push_back(viewInObjectFrame(scene, set.T_LinT_mm, v.angle_deg, o));
		angles_deg.push_back(v.angle_deg);
		edges.push_back(makeViewEdges(left, calib, set.T_LinT_mm, v.angle_deg));
	}
	WireFrame all = integrateViews(std::move(views), angles_deg, edges, o);
	all.name = set.object;
	return all;
}

WireFrame integrateViews(std::vector<WireFrame> views, const std::vector<double>& angles_deg,
                         const std::vector<ViewEdges>& edges, const TurntableOptions& o)
{
	WireFrame all;
	all.frame = WireFrameFrame::Object;
	all.conics = fitRimsAcrossViews(views, o.rims);
	completeRimsFromImages(all.conics, edges, o.rim_images);
	const auto chord_rims = rimsFromChords(views, edges, all.conics, o.rim_chords, o.rim_images);
	all.conics.insert(all.conics.end(), chord_rims.begin(), chord_rims.end());
	keepFeaturesSeenFromNearViews(views, angles_deg, o.support, edges);
	for (const auto& v : views)
	{
		all.lines.insert(all.lines.end(), v.lines.begin(), v.lines.end());
		all.conics.insert(all.conics.end(), v.conics.begin(), v.conics.end());
	}
	mergeDuplicates(all, o.merge);
	renumber(all);
	return all;
}

}  // namespace mrolr::model
