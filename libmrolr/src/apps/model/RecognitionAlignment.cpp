#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <opencv2/imgcodecs.hpp>

#include <optional>
#include <stdexcept>

namespace mrolr::apps
{
namespace
{
/** Turn about +z of @p T (deg, in (−180, 180]). */
double yawDeg(const Eigen::Isometry3d& T)
{
	return std::atan2(T.linear()(1, 0), T.linear()(0, 0)) * 180 / M_PI;
}

Eigen::Isometry3d turnAboutZ(double angle_deg)
{
	return Eigen::Isometry3d(Eigen::AngleAxisd(angle_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
}

model::WireFrame moved(const model::WireFrame& wf, const Eigen::Isometry3d& T)
{
	return model::transformWireFrame(wf, T, model::WireFrameFrame::Object);
}

void append(model::WireFrame& to, const model::WireFrame& from)
{
	to.lines.insert(to.lines.end(), from.lines.begin(), from.lines.end());
	to.conics.insert(to.conics.end(), from.conics.begin(), from.conics.end());
}

/** The accumulated model with @p view_M added, duplicates merged, ids unique for the matcher. */
void integrateInto(model::WireFrame& acc, const model::WireFrame& view_M,
                   const model::MergeOptions& merge)
{
	append(acc, view_M);
	model::mergeDuplicates(acc, merge);
	model::renumber(acc);
}

/** Length-weighted centroid of the features (mm). */
Eigen::Vector3d centroidOf(const model::WireFrame& wf)
{
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	double w = 0;
	for (const auto& s : model::sampleWireFrame(wf, 2.0))
		sum += s.weight_mm * s.p, w += s.weight_mm;
	return w > 0 ? Eigen::Vector3d(sum / w) : sum;
}

/** Does the turn about +z by @p deg carry @p truth onto itself (within 1 mm)? */
bool isSymmetry(const model::WireFrame& truth, double deg)
{
	model::QualityOptions tight;
	tight.tol_mm = 1, tight.max_angle_deg = 5;
	const auto q = model::compareToTruth(moved(truth, turnAboutZ(deg)), truth, tight);
	return q.recovered_fraction >= 0.95 && q.false_features == 0;
}

/** The turn about +z (deg) nearest to the error @p dT that maps @p truth onto itself: a multiple
 * of 90° (boxes), or dT's own turn for a body of revolution (a turn by 37° maps it onto
 * itself), else 0. */
double nearestSymmetryDeg(const Eigen::Isometry3d& dT, const model::WireFrame& truth)
{
	const double yaw = yawDeg(dT);
	if (isSymmetry(truth, 37.0)) return yaw;  // a body of revolution: every turn is one
	const double quarter = 90 * std::round(yaw / 90);
	return quarter != 0 && isSymmetry(truth, quarter) ? quarter : 0.0;
}

}  // namespace

std::vector<ViewRegistration> registerViews(const std::vector<AlignView>& views,
                                            double seed_angle_deg, const AlignContext& c)
{
	const size_t seed = static_cast<size_t>(c.align.seed_view);
	if (seed >= views.size())
		throw std::invalid_argument("alignment by recognition: seed_view " + std::to_string(seed) +
		                            " but there are " + std::to_string(views.size()) + " views");
	if (model::featureCount(views[seed].wf_T) < 2)
		throw std::invalid_argument(
		    "alignment by recognition: the seed view " + std::to_string(seed) + " has " +
		    std::to_string(model::featureCount(views[seed].wf_T)) +
		    " features on the object; it seeds the model and needs at least 2");
	std::vector<ViewRegistration> regs(views.size());
	for (size_t i = 0; i < regs.size(); ++i)
		regs[i].view = i, regs[i].features = model::featureCount(views[i].wf_T);
	regs[seed].registered = true, regs[seed].T_VinM = turnAboutZ(-seed_angle_deg);
	regs[seed].turn_deg = seed_angle_deg;
	model::WireFrame acc = moved(views[seed].wf_T, regs[seed].T_VinM);
	model::renumber(acc);
	for (int pass = 1; pass <= c.align.passes; ++pass)
		for (auto& r : regs)
		{
			if (r.registered) continue;
			matchView(r, views[r.view], acc, c);
			if (!r.registered) continue;
			r.pass = pass, r.turn_deg = -yawDeg(r.T_VinM);  // p_M = Rz(−angle) · p_T
			integrateInto(acc, moved(views[r.view].wf_T, r.T_VinM), c.turntable.merge);
		}
	return regs;
}

namespace
{
cv::Mat readImage(const std::string& path)
{
	cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
	if (img.empty()) throw std::runtime_error("cannot read turntable image '" + path + "'");
	return img;
}

/** Every view reconstructed and moved into the turntable frame (not turned), cropped; its left
 * image's edges posed in the turntable frame; its stereo pair when matching in the images. */
struct ViewsInTurntableFrame
{
	std::vector<AlignView> views;
	std::vector<model::ViewEdges> edges;
};

ViewsInTurntableFrame reconstructViews(const model::TurntableSet& set,
                                       const stereo::SceneOptions& so, const AlignContext& c)
{
	const stereo::StereoCalibration calib = stereo::loadStereoCalibration(set.calib_path);
	const auto io = c.align.match == "images" ? std::optional(imageOptions(c.align)) : std::nullopt;
	ViewsInTurntableFrame out;
	for (const auto& v : set.views)
	{
		const cv::Mat left = readImage(v.left_png), right = readImage(v.right_png);
		AlignView view;
		view.wf_T = model::viewInObjectFrame(
		    stereo::reconstructScene(left, right, calib, model::turntableSceneOptions(so)),
		                                     set.T_LinT_mm, 0.0, c.turntable);
		if (io) view.images = std::make_shared<recog::ImageVerifier>(left, right, calib, *io);
		out.views.push_back(std::move(view));
		out.edges.push_back(model::makeViewEdges(left, calib, set.T_LinT_mm, 0.0));
	}
	return out;
}

/** The turntable path's integration (model::integrateViews) of the registered views, each at its
 * recovered pose and turn. */
model::WireFrame integrate(const ViewsInTurntableFrame& views,
                           const std::vector<ViewRegistration>& regs,
                           const model::TurntableOptions& to)
{
	std::vector<model::WireFrame> views_M;
	std::vector<double> angles_deg;
	std::vector<model::ViewEdges> edges;
	for (const auto& r : regs)
	{
		if (!r.registered) continue;
		views_M.push_back(moved(views.views[r.view].wf_T, r.T_VinM));
		angles_deg.push_back(r.turn_deg);
		edges.push_back(views.edges[r.view]);
		edges.back().T_OinL = edges.back().T_OinL * r.T_VinM.inverse();
	}
	return model::integrateViews(std::move(views_M), angles_deg, edges, to);
}
}  // namespace

AlignmentResult buildByRecognition(const model::TurntableSet& set, const stereo::SceneOptions& so,
                                   const model::TurntableOptions& to, const AlignOptions& ao,
                                   const model::WireFrame* truth)
{
	const AlignContext c{alignmentRecognitionOptions(ao), ao, to, set.T_LinT_mm};
	if (static_cast<size_t>(ao.seed_view) >= set.views.size())
		throw std::invalid_argument("[align] seed_view = " + std::to_string(ao.seed_view) +
		                            " but the turntable set has " +
		                            std::to_string(set.views.size()) + " views");
	const auto views = reconstructViews(set, so, c);
	AlignmentResult out;
	out.views = registerViews(views.views, set.views[ao.seed_view].angle_deg, c);
	for (auto& r : out.views)
	{
		r.known_angle_deg = set.views[r.view].angle_deg;
		if (!r.registered) continue;
		measureRegistrationError(r, views.views[r.view].wf_T, truth);
		++out.registered;
	}
	out.model = integrate(views, out.views, to);
	out.model.name = set.object;
	return out;
}

void measureRegistrationError(ViewRegistration& r, const model::WireFrame& view_T,
                              const model::WireFrame* truth)
{
	const Eigen::Isometry3d T_true = turnAboutZ(-r.known_angle_deg);
	Eigen::Isometry3d dT = r.T_VinM * T_true.inverse();  // error, in frame M
	if (truth)
	{
		r.symmetry_deg = nearestSymmetryDeg(dT, *truth);
		dT = turnAboutZ(-r.symmetry_deg) * dT;
	}
	r.rot_err_deg = Eigen::AngleAxisd(dT.linear()).angle() * 180 / M_PI;
	const Eigen::Vector3d c = T_true * centroidOf(view_T);
	r.trans_err_mm = (dT * c - c).norm();
}

}  // namespace mrolr::apps
