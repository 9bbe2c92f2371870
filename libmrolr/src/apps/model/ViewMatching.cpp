#include <mrolr/apps/RecognitionAlignment.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Recognizer.h>

#include <sstream>
#include <stdexcept>

namespace mrolr::apps
{
namespace
{
std::string notRecognised(const recog::RecognitionResult& r)
{
	std::ostringstream s;
	s << "not recognised (best score " << r.score;
	if (r.image_score) s << ", image score " << *r.image_score;
	s << ")";
	return s.str();
}

void take(ViewRegistration& r, const recog::RecognitionResult& res, const Eigen::Isometry3d& T_VinM)
{
	r.registered = res.found;
	r.reason = res.found ? "" : notRecognised(res);
	r.T_VinM = T_VinM, r.score = res.score, r.level = res.level;
}

/** match = "shorter": 3D only, the shorter wire-frame as the recogniser's model. */
void matchShorter(ViewRegistration& r, const AlignView& view, const model::WireFrame& acc_M,
                  const AlignContext& c)
{
	recog::SceneContext up;  // the turntable's +z in T and in M
	if (c.align.upright_prior) up.up_S = Eigen::Vector3d::UnitZ();
	r.view_is_model = model::totalLength(view.wf_T) <= model::totalLength(acc_M);
	if (r.view_is_model)
	{
		const auto res = recog::Recognizer(view.wf_T, c.recognition).recognize(acc_M, up);
		take(r, res, res.T_OinS);
	}
	else
	{
		const auto res = recog::Recognizer(acc_M, c.recognition).recognize(view.wf_T, up);
		take(r, res, res.T_OinS.inverse());
	}
}

/** match = "images": the model so far recognised in the view (frame L), judged in its images. */
void matchInImages(ViewRegistration& r, const AlignView& view, const model::WireFrame& acc_M,
                   const AlignContext& c)
{
	if (!view.images) throw std::logic_error("match = images without the view's images");
	const Eigen::Isometry3d T_TinL = c.T_LinT_mm.inverse();
	const auto scene_L =
	    model::transformWireFrame(view.wf_T, T_TinL, model::WireFrameFrame::LeftCamera);
	const Eigen::Vector3d up_L = T_TinL.linear() * Eigen::Vector3d::UnitZ();
	recog::SceneContext context;
	if (c.align.upright_prior) context.up_S = up_L;
	context.images = std::cref(*view.images);
	const auto res = recog::Recognizer(acc_M, c.recognition).recognize(scene_L, context);
	// p_L = T_MinL · p_M and p_T = T_LinT · p_L
	take(r, res, (c.T_LinT_mm * res.T_OinS).inverse());
}
}  // namespace

void matchView(ViewRegistration& r, const AlignView& view, const model::WireFrame& acc_M,
               const AlignContext& c)
{
	if (r.features < 2)
	{
		r.reason = "view has " + std::to_string(r.features) + " features (needs 2)";
		return;
	}
	try
	{
		if (c.align.match == "images")
			matchInImages(r, view, acc_M, c);
		else
			matchShorter(r, view, acc_M, c);
	}
	catch (const std::invalid_argument& e)
	{
		r.reason = std::string("cannot be matched: ") + e.what();
	}
}

}  // namespace mrolr::apps
