// Davison's postponed update inside the project's filter (ActiveSlamFilter, update_method =
// postponed): a long run with random feature switches equals the same run with MRPT's batch update,
// and a tracking step leaves the O(N²) part of the filter's storage untouched.

#include <mrolr/slam/ActiveSlamFilter.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::slam;

namespace
{
const mrolr::base::LabmateModel kModel{};

struct World
{
	std::vector<Eigen::Vector3d> points;
	explicit World(int N)
	{
		std::mt19937 rng(17);
		std::uniform_real_distribution<double> b(-1.2, 1.2), r(3, 7), h(1.5, 3.0);
		for (int i = 0; i < N; ++i)
		{
			const double a = b(rng), d = r(rng);
			points.emplace_back(d * std::sin(a), h(rng), d * std::cos(a));
		}
	}
};

ActiveSlamFilter makeFilter(UpdateMethod m, const World& w)
{
	SlamOptions o;
	o.update_method = m;
	ActiveSlamFilter f(o, kModel);
	for (size_t i = 0; i < w.points.size(); ++i)
		f.initialiseFeature(
		    "p" + std::to_string(i),
		    predictMeasurement(Eigen::Vector3d::Zero(), w.points[i], o.head.constants));
	return f;
}

/** @p steps predictions and measurements; the measured feature changes every 1–6 steps. */
void drive(ActiveSlamFilter& f, const World& w, int steps)
{
	std::mt19937 rng(4);
	std::normal_distribution<double> n(0, 1);
	std::uniform_int_distribution<size_t> pick(0, w.points.size() - 1);
	std::uniform_int_distribution<int> len(1, 6);
	Eigen::Vector3d truth = Eigen::Vector3d::Zero();
	size_t i = 0;
	for (int k = 0, left = 0; k < steps; ++k, --left)
	{
		if (left == 0) i = pick(rng), left = len(rng);
		const mrolr::base::WheelControl u{0.05 + 0.02 * n(rng), 0.05 + 0.02 * n(rng), 1.0};
		truth = kModel.move(truth, u);
		f.predict(u);
		Eigen::Vector3d h = predictMeasurement(truth, w.points[i], f.options().head.constants);
		h += Eigen::Vector3d(0.002 * n(rng), 0.01 * n(rng), 0.002 * n(rng));
		f.update({Observation{i, h}});
	}
}

TEST(PostponedFilter, LongRunEqualsMrptBatchUpdate)
{
	const World w(20);
	ActiveSlamFilter batch = makeFilter(UpdateMethod::Batch, w);
	ActiveSlamFilter postponed = makeFilter(UpdateMethod::Postponed, w);
	drive(batch, w, 300);
	drive(postponed, w, 300);
	const Eigen::VectorXd xb = batch.stateVector(), xp = postponed.stateVector();
	const Eigen::MatrixXd Pb = batch.covariance(), Pp = postponed.covariance();
	EXPECT_LT((xp - xb).norm() / xb.norm(), 1e-9);
	EXPECT_LT((Pp - Pb).norm() / Pb.norm(), 1e-9);
	EXPECT_GT((Pb - makeFilter(UpdateMethod::Batch, w).covariance()).norm(), 1e-3 * Pb.norm())
	    << "the run must have changed the map covariance";
}

TEST(PostponedFilter, TrackingStepLeavesOtherBlocksOfStorageUntouched)
{
	const World w(12);
	ActiveSlamFilter f = makeFilter(UpdateMethod::Postponed, w);
	drive(f, w, 40);  // correlates the vehicle with every feature
	f.predict({0.05, 0.05, 1});
	f.update({Observation{3, f.predictedMeasurement(3)}});
	const Eigen::MatrixXd stored = f.internal_getPkk().asEigen();
	for (int k = 0; k < 5; ++k)
	{
		f.predict({0.05, 0.04, 1});
		f.update({Observation{3, f.predictedMeasurement(3) + Eigen::Vector3d(1e-3, 0, 0)}});
	}
	// Feature blocks j, k ≠ 3 of the stored P are exactly as before (the work is postponed) ...
	const Eigen::MatrixXd now = f.internal_getPkk().asEigen();
	EXPECT_EQ(now.bottomRightCorner(24, 24), stored.bottomRightCorner(24, 24));
	// ... and reading the full covariance brings them up to date.
	EXPECT_NE(f.covariance().bottomRightCorner(24, 24), stored.bottomRightCorner(24, 24));
}

}  // namespace
