#include <mrolr/recog/Recognizer.h>

namespace mrolr::recog
{
RecognitionTimes& RecognitionTimes::operator+=(const RecognitionTimes& o)
{
	cliques_ms += o.cliques_ms, verify_3d_ms += o.verify_3d_ms;
	image_score_ms += o.image_score_ms, image_refine_ms += o.image_refine_ms;
	plane_ms += o.plane_ms;
	return *this;
}

RecognitionTimes RecognitionTimes::scaled(double f) const
{
	return {f * cliques_ms, f * verify_3d_ms, f * image_score_ms, f * image_refine_ms,
	        f * plane_ms};
}

double RecognitionTimes::total_ms() const
{
	return cliques_ms + verify_3d_ms + image_score_ms + image_refine_ms + plane_ms;
}

}  // namespace mrolr::recog
