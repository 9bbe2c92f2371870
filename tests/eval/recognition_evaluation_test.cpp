// The recognition evaluation harness: truth geometry, the rendered set, the options.
#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace mrolr::eval;

namespace
{
EvaluationOptions shippedOptions()
{
	EvaluationOptions o;
	o.loadFromConfigFile(
	    mrpt::config::CConfigFile(mrolr::util::requireProjectFile("config/recognition.ini")),
	    "evaluation");
	return o;
}

/** One generator per test: its EGL context must go before MRPT's static texture registry does
 * (a static generator is destroyed after it, at exit). */
std::unique_ptr<EvalSceneGenerator> makeGenerator()
{
	return makeSceneGenerator(shippedOptions());
}

Eigen::Matrix3d Rx(double deg)
{
	return Eigen::AngleAxisd(deg * M_PI / 180, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
}  // namespace

// Symmetries of the true wire-frames: the can is a body of revolution, the lettered cube has
// none; the rotation error ignores what a symmetry cannot tell.
TEST(RenderedEval, SymmetriesAndRotationError)
{
	const auto gen = makeGenerator();
	auto& g = *gen;
	EXPECT_EQ(symmetryAnglesDeg(g.truthWireFrame("can")), std::vector<double>{-1});
	EXPECT_EQ(symmetryAnglesDeg(g.truthWireFrame("alphabet_cube")), std::vector<double>{0});
	const Eigen::Matrix3d R = Rx(30), yawed = R * mrolr::sim::R_aboutZ(77);
	EXPECT_NEAR(rotationErrorDeg(R, yawed, {-1}), 0, 1e-6);
	EXPECT_NEAR(rotationErrorDeg(R, yawed, {0}), 77, 1e-6);
	EXPECT_NEAR(rotationErrorDeg(R, R * Rx(5), {-1}), 5, 1e-6);
	EXPECT_NEAR(rotationErrorDeg(R, R * mrolr::sim::R_aboutZ(180), {0, 180}), 0, 1e-6);
}

// The set is fixed: the same scene twice is the same reconstruction; objects are in view.
TEST(RenderedEval, ScenesAreDeterministicAndShowTheirObjects)
{
	const auto gen = makeGenerator();
	auto& g = *gen;
	const EvalScene a = g.make(1), b = g.make(1);
	ASSERT_EQ(a.scene.lines.size(), b.scene.lines.size());
	ASSERT_FALSE(a.scene.lines.empty());
	EXPECT_TRUE(a.scene.lines[0].p1.isApprox(b.scene.lines[0].p1));
	ASSERT_EQ(a.objects.size(), b.objects.size());
	ASSERT_GE(a.objects.size(), 3u);
	for (const auto& o : a.objects)
	{
		EXPECT_GE(o.visible_fraction, 0.0);
		EXPECT_LE(o.visible_fraction, 1.0);
	}
	// the support plane in L: every object's origin (its base) on it, its +z along the normal
	EXPECT_NEAR(a.plane_L.n_S.norm(), 1.0, 1e-9);
	EXPECT_NEAR(a.plane_L.n_S.dot(a.up_L), 1.0, 1e-9);
	for (const auto& o : a.objects)
	{
		EXPECT_NEAR(a.plane_L.height_mm(o.T_OinL.translation()), 0.0, 0.5) << o.model;
		EXPECT_GT((o.T_OinL.linear() * Eigen::Vector3d::UnitZ()).dot(a.plane_L.n_S), 0.9999)
		    << o.model;
	}
	EXPECT_GT(a.objects[0].visible_fraction + a.objects[1].visible_fraction, 0.5);
}

// The set evaluated as a whole: one case per scene and model, scene by scene in model order; the
// observer sees each scene once with what its cases found; a model is present exactly when its
// object stands in the scene.
TEST(RenderedEval, SetHasACasePerSceneAndModel)
{
	EvaluationOptions o = shippedOptions();
	o.scenes = 2;
	const auto gen = makeSceneGenerator(o);
	const std::vector<mrolr::model::WireFrame> models = {gen->truthWireFrame("can"),
	                                                     gen->truthWireFrame("drink_package")};
	SetSearchOptions search;
	search.recognition.loadFromConfigFile(
	    mrpt::config::CConfigFile(mrolr::util::requireProjectFile("config/recognition.ini")),
	    "recognition");
	struct Seen
	{
		int index = 0;
		std::vector<bool> present, found;  ///< per model
	};
	std::vector<Seen> seen;
	const auto observe =
	    [&](const EvalScene& s, const std::vector<mrolr::recog::RecognitionResult>& found)
	{
		Seen v;
		v.index = s.index;
		for (size_t i = 0; i < models.size(); ++i)
		{
			v.present.push_back(s.find(models[i].name) != nullptr);
			v.found.push_back(found.at(i).found);
		}
		seen.push_back(v);
	};
	const auto cases = evaluateSet(*gen, models, search, observe);
	ASSERT_EQ(seen.size(), 2u);
	ASSERT_EQ(cases.size(), 4u);
	for (size_t k = 0; k < cases.size(); ++k)
	{
		const size_t scene = k / 2, model = k % 2;
		EXPECT_EQ(cases[k].scene, static_cast<int>(scene));
		EXPECT_EQ(cases[k].model, models[model].name);
		EXPECT_EQ(seen[scene].index, static_cast<int>(scene));
		EXPECT_EQ(cases[k].present, seen[scene].present[model]);
		EXPECT_EQ(cases[k].found, seen[scene].found[model]);
		EXPECT_EQ(cases[k].rot_err_deg >= 0, cases[k].present && cases[k].found);
	}
}

// A model named after no object of the world has no truth to be compared with.
TEST(RenderedEval, AModelOfNoObjectIsAnError)
{
	const auto gen = makeGenerator();
	mrolr::model::WireFrame wf = gen->truthWireFrame("can");
	wf.name = "no_such_object";
	const auto path = (fs::temp_directory_path() / "mrolr_eval_no_such_object.wf").string();
	mrolr::model::saveWireFrame(wf, path);
	EXPECT_THROW(databaseModels(*gen, {path}), std::runtime_error);
	EXPECT_EQ(databaseModels(*gen, {}).size(), truthModels(*gen).size());
	fs::remove(path);
}

// [evaluation] keys are checked: a malformed or out-of-range value names the key.
TEST(RenderedEval, BadEvaluationKeysNameTheKey)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("evaluation", "scenes", "zero");
	EvaluationOptions o;
	try
	{
		o.loadFromConfigFile(cfg, "evaluation");
		FAIL() << "no error";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("scenes"), std::string::npos);
	}
	mrpt::config::CConfigFileMemory cfg2;
	cfg2.write("evaluation", "max_view_distance_m", "0.5");  // below min_view_distance_m
	EXPECT_THROW(o.loadFromConfigFile(cfg2, "evaluation"), mrolr::util::ConfigError);
}
