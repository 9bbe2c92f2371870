// Misuse of the postponed tracker is reported with an exception that says what was wrong.

#include <mrolr/slam/PostponedTracker.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using mrolr::slam::PostponedTracker33;

namespace
{
using mrolr::test_support::messageOf;

struct Small
{
	Eigen::VectorXd x = Eigen::VectorXd::Zero(9);
	Eigen::MatrixXd P = Eigen::MatrixXd::Identity(9, 9);
};

TEST(PostponedTrackerErrors, StepsWithoutStartAreRejected)
{
	PostponedTracker33 t;
	EXPECT_NE(messageOf<std::logic_error>(
	              [&] {
		              t.predict({0, 0, 0}, Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Zero());
	              })
	              .find("predict: no feature is being tracked"),
	          std::string::npos);
	Small s;
	EXPECT_THROW(t.catchUp(s.x, s.P), std::logic_error);
	EXPECT_THROW(t.trackedFeature(), std::logic_error);
}

TEST(PostponedTrackerErrors, InconsistentSizesAreRejected)
{
	PostponedTracker33 t;
	Small s;
	const Eigen::MatrixXd P8 = Eigen::MatrixXd::Identity(8, 8);
	EXPECT_NE(messageOf<std::invalid_argument>([&] { t.start(s.x, P8, 0); }).find("P is 8x8"),
	          std::string::npos);
	const Eigen::VectorXd x8 = Eigen::VectorXd::Zero(8);
	EXPECT_NE(messageOf<std::invalid_argument>([&] { t.start(x8, P8, 0); }).find("state size 8"),
	          std::string::npos);
	EXPECT_NE(messageOf<std::out_of_range>([&] { t.start(s.x, s.P, 2); }).find("feature 2 of 2"),
	          std::string::npos);
	EXPECT_FALSE(t.tracking());
}

TEST(PostponedTrackerErrors, CatchUpIntoResizedStateIsRejected)
{
	PostponedTracker33 t;
	Small s;
	t.start(s.x, s.P, 1);
	t.predict({0.1, 0, 0}, Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity() * 1e-3);
	Eigen::VectorXd x12 = Eigen::VectorXd::Zero(12);
	Eigen::MatrixXd P12 = Eigen::MatrixXd::Identity(12, 12);
	EXPECT_NE(messageOf<std::invalid_argument>([&] { t.catchUp(x12, P12); }).find("changed size"),
	          std::string::npos);
}

TEST(PostponedTrackerErrors, IndefiniteInnovationCovarianceIsRejected)
{
	PostponedTracker33 t;
	Small s;
	t.start(s.x, s.P, 0);
	const Eigen::Matrix<double, 3, 6> H = Eigen::Matrix<double, 3, 6>::Identity();
	EXPECT_THROW(t.update<3>(Eigen::Vector3d::Zero(), H, -2 * Eigen::Matrix3d::Identity()),
	             std::runtime_error);
	// The failed update left the tracker unchanged.
	EXPECT_EQ(t.pendingSteps(), 0u);
	EXPECT_EQ(t.activeCovariance(), (Eigen::Matrix<double, 6, 6>::Identity()));
}

TEST(PostponedTrackerErrors, StopEndsTracking)
{
	PostponedTracker33 t;
	Small s;
	t.start(s.x, s.P, 1);
	EXPECT_EQ(t.trackedFeature(), 1u);
	t.stop(s.x, s.P);
	EXPECT_FALSE(t.tracking());
}

}  // namespace
