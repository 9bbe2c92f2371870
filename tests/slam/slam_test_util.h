#pragma once
// Shared helpers of the slam tests: a default filter and central differences.

#include <mrolr/base/LabmateModel.h>
#include <mrolr/slam/ActiveSlamFilter.h>

#include <Eigen/Core>

namespace slamtest
{
inline mrolr::slam::SlamOptions defaultOptions(
    mrolr::slam::UpdateMethod m = mrolr::slam::UpdateMethod::Sequential)
{
	mrolr::slam::SlamOptions o;
	o.update_method = m;
	return o;
}

template <class F>
Eigen::Matrix3d centralDiff(F f, const Eigen::Vector3d& x, double h = 1e-6)
{
	Eigen::Matrix3d J;
	for (int i = 0; i < 3; ++i)
	{
		Eigen::Vector3d a = x, b = x;
		a[i] += h;
		b[i] -= h;
		J.col(i) = (f(a) - f(b)) / (2 * h);
	}
	return J;
}
}  // namespace slamtest
