#include <mrolr/geometry/Frames.h>
#include <mrolr/io/Rawlog.h>
#include "SlamRecordings.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <sstream>
#include <stdexcept>

namespace mrolr::apps
{
namespace
{
std::string joined(const std::vector<std::string>& names)
{
	if (names.empty()) return "-";
	std::string out;
	for (const auto& n : names) out += (out.empty() ? "" : ";") + n;
	return out;
}

void writeEllipse(std::ostream& s, const char* key, const vision::ImageEllipse& e)
{
	s << " " << key << "=" << e.centre.x() << "," << e.centre.y() << "," << e.cov(0, 0) << ","
	  << e.cov(0, 1) << "," << e.cov(1, 1);
}

mrpt::Clock::time_point stamp(size_t step)
{
	return io::stampOf(double(step));
}

mrpt::obs::CObservationRobotPose::Ptr poseObs(const std::string& label, const Eigen::Vector3d& x,
                                              const Eigen::Vector3d& var, size_t step)
{
	auto o = mrpt::obs::CObservationRobotPose::Create();
	o->sensorLabel = label;
	o->timestamp = stamp(step);
	o->pose.mean = mrpt::poses::CPose3D(geometry::vehicleToMrpt(x));
	o->pose.cov.setZero();
	o->pose.cov(0, 0) = var[0], o->pose.cov(1, 1) = var[1], o->pose.cov(3, 3) = var[2];
	return o;
}

mrpt::obs::CSensoryFrame frameOf(size_t k, const SlamStepLog& st)
{
	mrpt::obs::CSensoryFrame sf;
	for (const auto& r : st.records)
	{
		auto c = mrpt::obs::CObservationComment::Create();
		c->sensorLabel = "SLAM_DECISION";
		c->timestamp = stamp(k);
		c->text = decisionText(k, r);
		sf.insert(c);
	}
	sf.insert(poseObs("SLAM_ESTIMATE", st.x_est, st.var_est, k));
	sf.insert(poseObs("GROUND_TRUTH", st.x_true, Eigen::Vector3d::Zero(), k));
	return sf;
}
}  // namespace

std::string decisionText(size_t step, const vision::CycleRecord& r)
{
	const auto& m = r.measurement;
	std::ostringstream s;
	s << "step=" << step << " feature=" << (r.measured ? r.label : "-") << " vs_rad3=" << r.vs;
	writeEllipse(s, "ellipse_left_px", m.ellipse_left);
	writeEllipse(s, "ellipse_right_px", m.ellipse_right);
	s << " n_sigma=" << m.ellipse_left.n_sigma << " score_left=" << m.left.score
	  << " score_right=" << m.right.score << " found=" << m.found << " accepted=" << r.accepted
	  << " added=" << joined(r.added) << " deleted=" << joined(r.deleted)
	  << " saccade=" << r.saccade << " measurements_lost=" << r.measurements_lost
	  << " waiting=" << r.waiting;
	return s.str();
}

void writeDecisionRawlog(const std::string& path, const std::vector<SlamStepLog>& steps)
{
	mrpt::io::CFileGZOutputStream file;
	if (!file.open(path, 1)) throw std::runtime_error(path + ": cannot write");
	auto out = mrpt::serialization::archiveFrom(file);
	for (size_t k = 0; k < steps.size(); ++k)
	{
		mrpt::obs::CActionCollection acts;
		mrpt::obs::CActionRobotMovement2D move;
		move.timestamp = stamp(k);
		const auto& prev = steps[k == 0 ? 0 : k - 1].x_dr;
		move.computeFromOdometry(
		    geometry::vehicleToMrpt(steps[k].x_dr) - geometry::vehicleToMrpt(prev),
		    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
		acts.insert(move);
		out << acts << frameOf(k, steps[k]);
	}
}

}  // namespace mrolr::apps
