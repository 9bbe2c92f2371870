#include <mrolr/arm/RtxKdl.h>

#include <kdl/joint.hpp>
#include <kdl/segment.hpp>

namespace mrolr::arm
{
KDL::Chain rtxKdlChain(const RtxOptions& o, double q1_rad, double scale)
{
	using KDL::Frame;
	using KDL::Joint;
	using KDL::Segment;
	const double half_pi = M_PI / 2;
	KDL::Chain c;
	// A segment's tip is joint(q) · f_tip: Rz(q)·DH(a, α, d, 0) = DH(a, α, d, q) for revolute
	// joints, Tz(d1)·Rz(q1) = Rz(q1)·Tz(d1) for the column.
	c.addSegment(Segment(Joint(Joint::TransZ), Frame::DH(0, 0, 0, q1_rad)));
	c.addSegment(Segment(Joint(Joint::RotZ), Frame::DH(o.a2_mm * scale, 0, 0, 0)));
	c.addSegment(Segment(Joint(Joint::RotZ), Frame::DH(o.a3_mm * scale, 0, 0, 0)));
	c.addSegment(Segment(Joint(Joint::RotZ), Frame::DH(0, half_pi, 0, 0)));
	c.addSegment(Segment(Joint(Joint::RotZ), Frame::DH(0, half_pi, 0, 0)));
	c.addSegment(Segment(Joint(Joint::RotZ), Frame::DH(0, 0, o.d6_mm * scale, 0)));
	return c;
}

KDL::JntArray toKdl(const RtxJoints& j, double scale)
{
	KDL::JntArray q(6);
	q(0) = j.d1_mm * scale;
	for (unsigned i = 1; i < 6; ++i) q(i) = j.q_rad[i];
	return q;
}

RtxJoints fromKdl(const KDL::JntArray& q, double q1_rad, double scale)
{
	RtxJoints j;
	j.d1_mm = q(0) / scale;
	j.q_rad[0] = q1_rad;
	for (unsigned i = 1; i < 6; ++i) j.q_rad[i] = q(i);
	return j;
}

KDL::Frame toKdl(const Eigen::Isometry3d& T, double scale)
{
	const Eigen::Matrix3d R = T.linear();
	const Eigen::Vector3d t = T.translation() * scale;
	return KDL::Frame(KDL::Rotation(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0),
	                                R(2, 1), R(2, 2)),
	                  KDL::Vector(t.x(), t.y(), t.z()));
}

Eigen::Isometry3d fromKdl(const KDL::Frame& F, double scale)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	for (int r = 0; r < 3; ++r)
	{
		for (int c = 0; c < 3; ++c) T.matrix()(r, c) = F.M(r, c);
		T.matrix()(r, 3) = F.p(r) / scale;
	}
	return T;
}

}  // namespace mrolr::arm
