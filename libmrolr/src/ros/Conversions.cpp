// MROLR ⇄ ROS 1 messages (Conversions.h).
#include <mrolr/geometry/Frames.h>
#include <mrolr/ros/Conversions.h>

#include <opencv2/imgproc.hpp>
#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace mrolr::ros
{
namespace
{
/** The offset as a whole ROS time: the run's time is added as a duration, so it keeps its
 * nanoseconds (1.7e9 + t as one double would round t to 2.4e-7 s). */
const ::ros::Time kOffset(static_cast<uint32_t>(io::kTimeOffset_s), 0);
}  // namespace

::ros::Time toRosTime(double time_s)
{
	return kOffset + ::ros::Duration(time_s);
}

double fromRosTime(const ::ros::Time& t)
{
	return secondsOf(t - kOffset);
}

double secondsOf(const ::ros::Duration& d)
{
	return double(d.sec) + double(d.nsec) / 1e9;
}

namespace
{
std_msgs::Header header(double time_s, const std::string& frame_id)
{
	std_msgs::Header h;
	h.stamp = toRosTime(time_s);
	h.frame_id = frame_id;
	return h;
}
}  // namespace

sensor_msgs::Image toImageMsg(const mrpt::img::CImage& img, double time_s,
                              const std::string& frame_id)
{
	const cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (m.depth() != CV_8U || (m.channels() != 1 && m.channels() != 3))
		throw std::invalid_argument("toImageMsg: only 8-bit images with 1 or 3 channels, not " +
		                            std::to_string(m.channels()) + " channels of depth " +
		                            std::to_string(m.depth()));
	sensor_msgs::Image out;
	out.header = header(time_s, frame_id);
	out.height = static_cast<uint32_t>(m.rows);
	out.width = static_cast<uint32_t>(m.cols);
	out.encoding = m.channels() == 1 ? sensor_msgs::image_encodings::MONO8
	                                 : sensor_msgs::image_encodings::BGR8;
	out.is_bigendian = 0;
	out.step = static_cast<uint32_t>(m.cols * m.channels());
	out.data.resize(size_t(out.step) * out.height);
	for (int r = 0; r < m.rows; ++r)
		std::memcpy(&out.data[size_t(r) * out.step], m.ptr(r), out.step);
	return out;
}

mrpt::img::CImage fromImageMsg(const sensor_msgs::Image& m)
{
	namespace enc = sensor_msgs::image_encodings;
	int channels = 0;
	if (m.encoding == enc::MONO8) channels = 1;
	if (m.encoding == enc::BGR8 || m.encoding == enc::RGB8) channels = 3;
	if (!channels)
		throw std::invalid_argument("fromImageMsg: encoding '" + m.encoding +
		                            "' (expected mono8, bgr8 or rgb8)");
	if (m.step < m.width * channels || m.data.size() < size_t(m.step) * m.height)
		throw std::invalid_argument("fromImageMsg: a " + std::to_string(m.width) + "x" +
		                            std::to_string(m.height) + " " + m.encoding + " image with step " +
		                            std::to_string(m.step) + " and " + std::to_string(m.data.size()) +
		                            " bytes");
	cv::Mat out(int(m.height), int(m.width), channels == 1 ? CV_8UC1 : CV_8UC3);
	for (uint32_t r = 0; r < m.height; ++r)
		std::memcpy(out.ptr(int(r)), &m.data[size_t(r) * m.step], size_t(m.width) * channels);
	if (m.encoding == enc::RGB8) cv::cvtColor(out, out, cv::COLOR_RGB2BGR);
	return mrpt::img::CImage(out, mrpt::img::DEEP_COPY);
}

sensor_msgs::CameraInfo toCameraInfo(const mrpt::img::TCamera& cam, double time_s,
                                     const std::string& frame_id)
{
	sensor_msgs::CameraInfo c;
	c.header = header(time_s, frame_id);
	c.width = cam.ncols;
	c.height = cam.nrows;
	c.distortion_model = "plumb_bob";
	c.D = {0, 0, 0, 0, 0};
	c.K = {cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1};
	c.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
	c.P = {cam.fx(), 0, cam.cx(), 0, 0, cam.fy(), cam.cy(), 0, 0, 0, 1, 0};
	return c;
}

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& T)
{
	geometry_msgs::Pose p;
	p.position.x = T.translation().x(), p.position.y = T.translation().y();
	p.position.z = T.translation().z();
	const Eigen::Quaterniond q(T.linear());
	p.orientation.w = q.w(), p.orientation.x = q.x(), p.orientation.y = q.y();
	p.orientation.z = q.z();
	return p;
}

Eigen::Isometry3d fromPoseMsg(const geometry_msgs::Pose& p)
{
	const Eigen::Quaterniond q(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
	if (std::abs(q.norm() - 1.0) > 1e-6)
		throw std::invalid_argument("fromPoseMsg: the orientation is not a unit quaternion");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = q.toRotationMatrix();
	T.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
	return T;
}

geometry_msgs::TransformStamped toTransformMsg(const Eigen::Isometry3d& T,
                                               const std::string& parent,
                                               const std::string& child, double time_s)
{
	geometry_msgs::TransformStamped t;
	t.header = header(time_s, parent);
	t.child_frame_id = child;
	const auto p = toPoseMsg(T);
	t.transform.translation.x = p.position.x, t.transform.translation.y = p.position.y;
	t.transform.translation.z = p.position.z;
	t.transform.rotation = p.orientation;
	return t;
}

Eigen::Isometry3d planarPose(const Eigen::Vector3d& xv)
{
	const auto m = geometry::vehicleToMrpt(xv);  // x = z, y = x, yaw = φ
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::AngleAxisd(m.phi(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
	T.translation() = Eigen::Vector3d(m.x(), m.y(), 0);
	return T;
}

Eigen::Vector3d planarPoseFrom(const geometry_msgs::Pose& p)
{
	const auto& q = p.orientation;
	const double yaw = std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
	return geometry::vehicleFromMrpt(mrpt::poses::CPose2D(p.position.x, p.position.y, yaw));
}

namespace
{
constexpr int kPlanarAxes[3] = {0, 1, 5};  // z → x, x → y, φ → yaw in (x, y, z, roll, pitch, yaw)
}

boost::array<double, 36> planarCovariance(const Eigen::Matrix3d& P, double unobserved_var)
{
	boost::array<double, 36> c{};
	for (int i : {2, 3, 4}) c[i * 6 + i] = unobserved_var;
	for (int i = 0; i < 3; ++i)
		for (int k = 0; k < 3; ++k) c[kPlanarAxes[i] * 6 + kPlanarAxes[k]] = P(i, k);
	return c;
}

Eigen::Matrix3d planarCovarianceFrom(const boost::array<double, 36>& c)
{
	Eigen::Matrix3d P;
	for (int i = 0; i < 3; ++i)
		for (int k = 0; k < 3; ++k) P(i, k) = c[kPlanarAxes[i] * 6 + kPlanarAxes[k]];
	return P;
}

nav_msgs::Odometry toOdometryMsg(const Eigen::Vector3d& xv, double time_s)
{
	nav_msgs::Odometry o;
	o.header = header(time_s, "odom");
	o.child_frame_id = "base_link";
	o.pose.pose = toPoseMsg(planarPose(xv));
	return o;
}

sensor_msgs::JointState headJointsMsg(const Eigen::Vector4d& head_rad, double time_s)
{
	sensor_msgs::JointState j;
	j.header = header(time_s, "");
	j.name = {"pan", "tilt", "verg_left", "verg_right"};
	j.position = {head_rad[0], head_rad[1], head_rad[2], head_rad[3]};
	return j;
}

std::vector<double> jointPositions(const sensor_msgs::JointState& m,
                                   const std::vector<std::string>& names)
{
	if (m.position.size() != m.name.size())
		throw std::invalid_argument("JointState: " + std::to_string(m.name.size()) + " names but " +
		                            std::to_string(m.position.size()) + " positions");
	std::vector<double> out;
	for (const auto& n : names)
	{
		const auto it = std::find(m.name.begin(), m.name.end(), n);
		if (it == m.name.end()) throw std::invalid_argument("JointState: no joint '" + n + "'");
		out.push_back(m.position[size_t(it - m.name.begin())]);
	}
	return out;
}

}  // namespace mrolr::ros
