#include "PostponedRunner.h"

namespace mrolr::bench
{
PostponedRunner::PostponedRunner(BenchProblem& problem, size_t feature)
    : problem_(problem), x_(problem.x0), P_(problem.P0)
{
	tracker_.start(x_, P_, feature);
}

void PostponedRunner::step()
{
	const base::WheelControl u = problem_.control();
	Eigen::Vector3d xv = tracker_.vehicle();
	const base::LabmateModel& m = problem_.model;
	tracker_.predict(m.move(xv, u), m.jacobianState(xv, u), m.processNoise(xv, u));
	xv = tracker_.vehicle();
	const Eigen::Vector3d y = tracker_.feature();
	const Eigen::Vector3d z = problem_.measure(xv, y);
	const auto J = slam::measurementJacobians(xv, y, problem_.head);
	Eigen::Matrix<double, 3, 6> H;
	H << J.H_xv, J.H_y;
	const Eigen::Vector3d nu =
	    slam::measurementDifference(z, slam::predictMeasurement(xv, y, problem_.head));
	tracker_.update<3>(nu, H, problem_.R);
}

}  // namespace mrolr::bench
