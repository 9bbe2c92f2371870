#include "SyntheticScenes.h"

#include <mrolr/model/ModelStats.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameIO.h>

#include <gtest/gtest.h>

#include <iostream>

using namespace mrolr;
using namespace mrolr::model;

TEST(SceneModel, CardsAndDiscAtOneMetreAreRecovered)
{
	WireFrame truth;
	const auto faces = test::cardsAndDisc(truth);
	const auto rig = stereo::test::testRig();
	cv::Mat L, R;
	stereo::test::renderPair(faces, rig, L, R);
	const WireFrame wf = sceneToWireFrame(stereo::reconstructScene(L, R, rig, stereo::SceneOptions()));
	const ModelQuality q = compareToTruth(wf, truth);
	printQuality(q, std::cout);
	writeWireFrame(wf, std::cout);
	EXPECT_GE(q.recovered_fraction, 0.6);
	EXPECT_LT(q.median_endpoint_error_mm, 3.0);
	EXPECT_LE(q.false_features, 1);
}
