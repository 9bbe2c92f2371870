#include "recog_test_util.h"

#include <mrolr/model/WireFrameIO.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <tuple>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
SceneNoise noisy()
{
	SceneNoise n;
	n.endpoint_sigma_mm = 0.5;
	n.fragment_probability = 0.5;
	n.missing_fraction = 0.2;
	return n;
}
}  // namespace

// The OpenGV point-based estimator alone, and both together, also recognise with exact poses.
TEST(RecognizerMisc, ArunAndBothPoseMethods)
{
	const auto objects = makeLabObjects();
	for (const PoseMethod method : {PoseMethod::Arun, PoseMethod::Both})
	{
		auto opts = RecognitionOptions::defaults();
		opts.pose_method = method;
		for (size_t k : {0u, 1u, 4u, 9u})
		{
			const auto T = tablePose(33.0 * k, 30, Eigen::Vector3d(0, -120, 750));
			const auto r = Recognizer(objects[k], opts).recognize(placeInScene(objects[k], T));
			ASSERT_TRUE(r.found) << int(method) << " " << objects[k].name;
			EXPECT_LT((r.T_OinS.matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-6) << int(method);
		}
	}
}

// The model area's automatic cliques (mrolr-model's method) also recognise exact scenes; an
// unknown method is refused.
TEST(RecognizerMisc, ModelAreaCliques)
{
	auto opts = RecognitionOptions::defaults();
	opts.auto_cliques = "model";
	const auto objects = makeLabObjects();
	for (size_t k : {0u, 1u, 6u})
	{
		const auto T = tablePose(20.0 * k, 35, Eigen::Vector3d(10, -120, 700));
		const Recognizer rec(objects[k], opts);
		EXPECT_FALSE(rec.table().cliques().empty());
		const auto r = rec.recognize(placeInScene(objects[k], T));
		ASSERT_TRUE(r.found) << objects[k].name;
		EXPECT_LT((r.T_OinS.matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-6);
	}
	opts.auto_cliques = "magic";
	EXPECT_THROW(Recognizer(objects[0], opts), std::invalid_argument);
}

// Noise kinds one at a time (endpoint noise, fragmentation, missing segments), each object.
TEST(RecognizerMisc, EachNoiseKindAlone)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	SceneNoise kinds[3];
	kinds[0].endpoint_sigma_mm = 1.0;
	kinds[1].fragment_probability = 1.0;
	kinds[2].missing_fraction = 0.3;
	for (int kind = 0; kind < 3; ++kind)
	{
		int ok = 0;
		for (size_t k = 0; k < objects.size(); ++k)
		{
			const auto ts = makeTableScene(objects, static_cast<int>(k), 2, kinds[kind], 77 + k);
			const auto r = Recognizer(objects[k], opts).recognize(ts.scene);
			ok += r.found && test::rotationErrorDeg(r.T_OinS, ts.T_OinS) < 3 &&
			      test::translationErrorMm(r.T_OinS, ts.T_OinS) < 6;
		}
		EXPECT_GE(ok, 9) << "noise kind " << kind;
	}
}

// Pan sweep (thesis 6.4): the object is in the third of five scene models; the sweep stops there.
TEST(RecognizerMisc, PanSweepFindsTheSceneHoldingTheObject)
{
	const auto objects = makeLabObjects();
	const auto cup = objects[1];
	std::vector<mrolr::model::WireFrame> sweep;
	auto others = objects;
	others.erase(others.begin() + 1);
	for (unsigned i = 0; i < 5; ++i)
		sweep.push_back(i == 2 ? makeTableScene(objects, 1, 2, noisy(), 900 + i).scene
		                       : makeTableScene(others, -1, 3, noisy(), 900 + i).scene);
	const Recognizer rec(cup, RecognitionOptions::defaults());
	const auto r = rec.searchSweep(sweep);
	ASSERT_TRUE(r.found);
	EXPECT_EQ(r.scene_index, 2);
	EXPECT_GT(r.confidence, 0.2);
	sweep.erase(sweep.begin() + 2);
	const auto none = rec.searchSweep(sweep);
	EXPECT_FALSE(none.found);
	EXPECT_FALSE(none.scene_index);
	EXPECT_FALSE(none.level);
	EXPECT_EQ(none.confidence, 0);
}

// An empty scene and a scene of one line: not found, no crash.
TEST(RecognizerMisc, EmptyAndTinyScenes)
{
	const Recognizer rec(makeCup(), RecognitionOptions::defaults());
	mrolr::model::WireFrame empty;
	EXPECT_FALSE(rec.recognize(empty).found);
	mrolr::model::WireFrame one;
	one.lines.push_back({1, {0, 0, 0}, {100, 0, 0}});
	EXPECT_FALSE(rec.recognize(one).found);
}

// Malformed .wf text is rejected by the reader with the line number (also a zero-length line);
// a model built in code with a non-finite conic reaches the recognizer, which names the element.
TEST(RecognizerMisc, MalformedWireFrames)
{
	std::istringstream bad("# mrolr wire-frame 1\nunits mm\nframe object\nline 1 0 0 0 1 0\n");
	EXPECT_THROW(mrolr::model::readWireFrame(bad, "bad.wf"), mrolr::model::WireFrameFormatError);
	std::istringstream zero(
	    "# mrolr wire-frame 1\nunits mm\nframe object\nline 1 0 0 0 0 0 0\nline 2 0 0 0 1 0 0\n");
	EXPECT_THROW(mrolr::model::readWireFrame(zero, "zero.wf"), mrolr::model::WireFrameFormatError);
	auto cup = makeCup();
	cup.conics[0].a = std::nan("");
	try
	{
		Recognizer rec(cup, RecognitionOptions::defaults());
		FAIL() << "a NaN radius was accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("conic"), std::string::npos) << e.what();
	}
}

namespace
{
void expectSameAnswer(const RecognitionResult& a, const RecognitionResult& b, const char* what)
{
	EXPECT_EQ(a.found, b.found) << what;
	EXPECT_EQ(a.T_OinS.matrix(), b.T_OinS.matrix()) << what;
	EXPECT_EQ(a.score, b.score) << what;
	EXPECT_EQ(a.level, b.level) << what;
	EXPECT_EQ(a.agreeing_cliques, b.agreeing_cliques) << what;
}
}  // namespace

// A Recognizer remembers the last scene's clusters and verified poses: the same scene searched
// again as a repeat gives the same answer without matching cliques; searched again without saying
// so, or any other scene said to be a repeat (one segment moved by 2 mm, another up direction,
// the object taken away), gives what a fresh Recognizer gives, cliques matched.
TEST(RecognizerMisc, ARepeatedSearchReusesItsHypothesesAndNothingElse)
{
	const auto objects = makeLabObjects();
	const size_t k = 1;
	const auto opts = RecognitionOptions::defaults();
	const auto ts = makeTableScene(objects, static_cast<int>(k), 2, noisy(), 4242);
	mrolr::model::WireFrame moved = ts.scene;
	ASSERT_FALSE(moved.lines.empty());
	moved.lines.front().p1 += Eigen::Vector3d(2, 0, 0);
	std::vector<mrolr::model::WireFrame> others = objects;
	others.erase(others.begin() + static_cast<std::ptrdiff_t>(k));
	const auto without = makeTableScene(others, -1, 2, noisy(), 4242).scene;
	SceneContext repeat;
	repeat.repeat = true;
	SceneContext up_repeat = repeat;
	up_repeat.up_S = Eigen::Vector3d(0, 1, 0);

	const Recognizer rec(objects[k], opts);
	const auto first = rec.recognize(ts.scene);
	ASSERT_TRUE(first.found);
	EXPECT_GT(first.times.cliques_ms, 0.0);
	const auto again = rec.recognize(ts.scene, repeat);
	expectSameAnswer(again, first, "same scene again");
	EXPECT_EQ(again.times.cliques_ms, 0.0) << "the repeat matched the cliques again";
	EXPECT_GT(rec.recognize(ts.scene).times.cliques_ms, 0.0) << "not said to be a repeat";

	for (const auto& [scene, context, what] :
	     {std::make_tuple(moved, repeat, "one segment moved"),
	      std::make_tuple(ts.scene, up_repeat, "an up direction given"),
	      std::make_tuple(without, repeat, "the object taken away")})
	{
		const auto r = rec.recognize(scene, context);
		EXPECT_GT(r.times.cliques_ms, 0.0) << what;
		expectSameAnswer(r, Recognizer(objects[k], opts).recognize(scene, context), what);
	}
	EXPECT_FALSE(rec.recognize(without, repeat).found);
	rec.recognize(ts.scene);
	expectSameAnswer(rec.recognize(ts.scene, repeat), first, "the first scene once more");
}

// The stage times are the parts of the search's time: none negative, together no more than ms.
TEST(RecognizerMisc, StageTimesArePartsOfTheSearchTime)
{
	const auto objects = makeLabObjects();
	const auto ts = makeTableScene(objects, 3, 2, noisy(), 4343);
	const auto r = Recognizer(objects[3], RecognitionOptions::defaults()).recognize(ts.scene);
	const auto& t = r.times;
	for (const double ms : {t.cliques_ms, t.verify_3d_ms, t.image_score_ms, t.image_refine_ms,
	                        t.plane_ms})
		EXPECT_GE(ms, 0.0);
	EXPECT_GT(t.cliques_ms, 0.0);
	EXPECT_EQ(t.image_score_ms + t.image_refine_ms + t.plane_ms, 0.0) << "no images were given";
	EXPECT_LE(t.total_ms(), r.ms);
}
