#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/sim/GroundTruth.h>
#include <mrolr/sim/ObjectVisual.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/Placement.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/util/Cli.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <random>
#include <stdexcept>

namespace mrolr::eval
{
namespace
{
using Rng = std::mt19937;

double uniform(Rng& rng, double lo, double hi)
{
	return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/** Radius (m) of the smallest vertical cylinder about O's z holding the wire-frame. */
double footprintRadius_m(const model::WireFrame& wf)
{
	double r = 0;
	for (const auto& s : model::sampleWireFrame(wf, 5)) r = std::max(r, s.p.head<2>().norm());
	return r / 1000;
}

/** A point on the table top in W (x, z) from table coordinates (along its length and depth). */
Eigen::Vector2d tableToW(const world::Table& t, double along_m, double across_m)
{
	const Eigen::Matrix3d R = sim::R_aboutVertical(t.yaw_deg * M_PI / 180);
	const Eigen::Vector3d p = R * Eigen::Vector3d(along_m, 0, across_m);
	return {t.x_m + p.x(), t.z_m + p.z()};
}

/** The objects of scene k: models drawn without repetition, footprints apart, near the centre. */
std::vector<world::PlacedObject> placeObjects(Rng& rng, const EvaluationOptions& o,
                                              const world::Table& t,
                                              const std::map<std::string, double>& radius_m,
                                              const Eigen::Vector2d& centre_table)
{
	std::vector<std::string> names;
	for (const auto& [n, r] : radius_m) names.push_back(n);
	std::shuffle(names.begin(), names.end(), rng);
	const int n = std::uniform_int_distribution<int>(o.min_objects, o.max_objects)(rng);
	std::vector<world::PlacedObject> placed;
	std::vector<Eigen::Vector3d> discs;  // along, across, radius (table coordinates)
	for (int tries = 0; tries < 500 && static_cast<int>(placed.size()) < n; ++tries)
	{
		const std::string& m = names[placed.size() % names.size()];
		const double r = radius_m.at(m), a = uniform(rng, 0, 2 * M_PI);
		const double d = o.cluster_radius_m * std::sqrt(uniform(rng, 0, 1));
		const Eigen::Vector2d p = centre_table + d * Eigen::Vector2d(std::cos(a), std::sin(a));
		bool ok = std::abs(p.x()) + r < t.length_m / 2 && std::abs(p.y()) + r < t.depth_m / 2;
		for (const auto& q : discs)
			ok = ok && (p - q.head<2>()).norm() > r + q.z() + o.object_gap_m;
		if (!ok) continue;
		const Eigen::Vector2d w = tableToW(t, p.x(), p.y());
		placed.push_back({m, m, t.name, w.x(), w.y(), uniform(rng, -180, 180)});
		discs.push_back({p.x(), p.y(), r});
	}
	if (static_cast<int>(placed.size()) < n)
		throw std::runtime_error("evaluation scene: cannot place " + std::to_string(n) +
		                         " objects apart within cluster_radius_m on table " + t.name);
	return placed;
}

struct Viewpoint
{
	Eigen::Isometry3d T_C0inW = Eigen::Isometry3d::Identity();
	geometry::HeadAngles angles;
};

/** The vehicle a random distance and bearing back from the fixated point, heading at it; the
 * head fixates the point (eqs 4.25–4.33) and pans a little off it. */
Viewpoint chooseViewpoint(Rng& rng, const EvaluationOptions& o, const geometry::BiSightHead& head,
                          const Eigen::Vector3d& p_fixInW)
{
	const double d = uniform(rng, o.min_view_distance_m, o.max_view_distance_m);
	const double psi = uniform(rng, -25, 25) * M_PI / 180;
	const Eigen::Vector3d xv(p_fixInW.z() - d * std::cos(psi), p_fixInW.x() - d * std::sin(psi),
	                         psi);
	Viewpoint v;
	v.T_C0inW = geometry::T_C0inW(xv, head.options().head_height_m);
	v.angles = head.fixate(v.T_C0inW.inverse() * p_fixInW);
	v.angles.pan += uniform(rng, -4, 4) * M_PI / 180;
	head.checkJointLimits(v.angles);
	return v;
}

cv::Mat greyOf(const mrpt::img::CImage& img)
{
	cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY).clone();
	if (m.channels() == 3) cv::cvtColor(m, m, cv::COLOR_BGR2GRAY);
	return m;
}
}  // namespace

const EvalObject* EvalScene::find(const std::string& model) const
{
	for (const auto& o : objects)
		if (o.model == model) return &o;
	return nullptr;
}

EvalSceneGenerator::EvalSceneGenerator(const EvaluationOptions& opts,
                                       const geometry::BiSightHead& head,
                                       const sim::RenderOptions& render,
                                       const stereo::SceneOptions& scene,
                                       std::map<std::string, world::ObjectShape> shapes)
    : opts_(opts),
      head_(head),
      scene_opts_(scene),
      lab_(world::World::load(util::requireProjectFile(opts.world))),
      shapes_(std::move(shapes)),
      renderer_(std::make_unique<sim::StereoRenderer>(head, render))
{
	if (!lab_.findTable(opts_.table))
		throw std::runtime_error(lab_.path + ": no table '" + opts_.table +
		                         "' ([evaluation] table)");
	for (const auto& [name, shape] : shapes_)
	{
		truth_[name] = sim::objectWireFrame(shape);
		truth_[name].name = name;
		radius_m_[name] = footprintRadius_m(truth_[name]);
	}
	lab_.objects.clear();
	base_scene_ = sim::buildLabScene(lab_).scene;
}

EvalSceneGenerator::~EvalSceneGenerator() = default;

const model::WireFrame& EvalSceneGenerator::truthWireFrame(const std::string& model) const
{
	const auto it = truth_.find(model);
	if (it == truth_.end()) throw std::runtime_error("no object definition for model " + model);
	return it->second;
}

EvalScene EvalSceneGenerator::make(int k)
{
	Rng rng(opts_.seed + static_cast<unsigned>(k));
	const world::Table& t = *lab_.findTable(opts_.table);
	const Eigen::Vector2d c(uniform(rng, -0.5, 0.5) * std::max(0.0, t.length_m - 0.6),
	                        uniform(rng, -0.5, 0.5) * std::max(0.0, t.depth_m - 0.5));
	world::World w = lab_;
	w.objects = placeObjects(rng, opts_, t, radius_m_, c);
	const Eigen::Vector2d cW = tableToW(t, c.x(), c.y());
	const world::PlacedObject centre{"", "", t.name, cW.x(), cW.y(), 0};
	const Eigen::Vector3d p_fixInW =
	    sim::T_OinW(w, centre).translation() + Eigen::Vector3d(0, opts_.fixation_height_m, 0);
	const Viewpoint v = chooseViewpoint(rng, opts_, head_, p_fixInW);
	EvalScene s;
	s.index = k;
	const sim::StereoFrame f = renderWith(w, v.T_C0inW, v.angles, static_cast<uint64_t>(k));
	s.left = greyOf(f.left), s.right = greyOf(f.right), s.render_s = f.render_s;
	s.calib = stereo::calibrationFromHead(head_, v.angles);
	s.up_L = head_.T_LinC0(v.angles).linear().transpose() * Eigen::Vector3d::UnitY();  // C0: y up
	const Eigen::Isometry3d T_WinL = (v.T_C0inW * head_.T_LinC0(v.angles)).inverse();
	const Eigen::Vector3d p_topInW =
	    p_fixInW - Eigen::Vector3d(0, opts_.fixation_height_m, 0);  // on the table top (m)
	s.plane_L = recog::SupportPlane::through(1000 * (T_WinL * p_topInW), s.up_L);
	reconstruct(s);
	for (const auto& ov : sim::objectViews(w, head_, v.T_C0inW, v.angles))
		s.objects.push_back(truthOf(ov, s.calib, f.depth_left_m));
	return s;
}

void EvalSceneGenerator::reconstruct(EvalScene& s) const
{
	const auto t0 = std::chrono::steady_clock::now();
	// the head's up direction lets stereo fit rims seen nearly edge-on as horizontal circles
	s.scene = model::sceneToWireFrame(
	    stereo::reconstructScene(s.left, s.right, s.calib, scene_opts_, s.up_L));
	s.scene.name = "scene_" + std::to_string(s.index);
	s.reconstruct_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

sim::StereoFrame EvalSceneGenerator::renderWith(const world::World& w,
                                                const Eigen::Isometry3d& T_C0inW,
                                                const geometry::HeadAngles& a, uint64_t frame)
{
	// a new scene per frame: the renderer keeps the objects of the scene it saw last
	auto scene = mrpt::opengl::COpenGLScene::Create();
	for (const auto& o : *base_scene_->getViewport()) scene->insert(o);
	for (const auto& o : w.objects)
	{
		auto vis = sim::objectVisual(shapes_.at(o.model));
		vis->setPose(sim::objectPoseMrpt(w, o));
		scene->insert(vis);
	}
	return renderer_->render(*scene, T_C0inW, a, frame);
}

EvalObject EvalSceneGenerator::truthOf(const sim::ObjectView& ov,
                                       const stereo::StereoCalibration& calib,
                                       const mrpt::math::CMatrixFloat& depth_m) const
{
	EvalObject o;
	o.model = ov.model;
	o.T_OinL = geometry::inMm(ov.T_OinL);
	o.visible_fraction = visibleFraction(truthWireFrame(ov.model), o.T_OinL, calib.K_left, depth_m,
	                                     opts_.visibility_depth_tol_mm);
	return o;
}

}  // namespace mrolr::eval
