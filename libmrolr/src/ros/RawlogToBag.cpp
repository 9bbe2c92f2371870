// A rawlog's records as ROS 1 messages in a bag (RawlogToBag.h).
#include <mrolr/io/Rawlog.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/RawlogToBag.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <stdexcept>

namespace mrolr::ros
{
namespace
{
class BagOut
{
 public:
	explicit BagOut(const std::string& path)
	{
		try
		{
			bag_.open(path, rosbag::bagmode::Write);
		}
		catch (const std::exception& e)
		{
			throw std::runtime_error("cannot write the bag " + path + ": " + e.what());
		}
	}
	~BagOut() { bag_.close(); }  // a bag is readable only once closed
	template <typename M>
	void write(const std::string& topic, double time_s, const M& msg)
	{
		bag_.write(topic, toRosTime(time_s), msg);
		++summary.messages[topic];
	}
	void tf(const geometry_msgs::TransformStamped& t, const std::string& topic = "/tf")
	{
		tf2_msgs::TFMessage m;
		m.transforms.push_back(t);
		write(topic, fromRosTime(t.header.stamp), m);
	}
	BagSummary summary;

 private:
	rosbag::Bag bag_;
};

/** A pair's image, read now: one pair in memory at a time. */
mrpt::img::CImage imageOf(const std::string& file)
{
	mrpt::img::CImage img;
	if (!img.loadFromFile(file)) throw std::runtime_error("cannot read the pair's image " + file);
	return img;
}

void writePair(const io::RawlogRecord& r, BagOut& out)
{
	const double t = r.time_s;
	out.write("/stereo/left/image_raw", t, toImageMsg(imageOf(r.left_file), t, "left_camera"));
	out.write("/stereo/right/image_raw", t, toImageMsg(imageOf(r.right_file), t, "right_camera"));
	out.write("/stereo/left/camera_info", t, toCameraInfo(r.camera, t, "left_camera"));
	out.write("/stereo/right/camera_info", t, toCameraInfo(r.camera, t, "right_camera"));
	out.tf(toTransformMsg(r.T_LcvInVehicle, "base_link", "left_camera", t));
	out.tf(toTransformMsg(r.T_RcvInLcv, "left_camera", "right_camera", t));
	++out.summary.pairs;
}

void writeState(const io::RawlogRecord& r, BagOut& out)
{
	const double t = r.time_s;
	out.write("/odom", t, toOdometryMsg(r.odometry_zxphi, t));
	out.tf(toTransformMsg(planarPose(r.odometry_zxphi), "odom", "base_link", t));
	out.write("/head/joint_states", t, headJointsMsg(r.head_rad, t));
	if (r.estimate_zxphi)
	{  // REP 105: world → odom is the estimate's correction of the dead reckoning
		geometry_msgs::PoseWithCovarianceStamped e;
		e.header.stamp = toRosTime(t);
		e.header.frame_id = "world";
		e.pose.pose = toPoseMsg(planarPose(*r.estimate_zxphi));
		e.pose.covariance = planarCovariance(r.estimate_P);
		out.write("/mrolr/estimate", t, e);
		out.tf(toTransformMsg(planarPose(*r.estimate_zxphi) * planarPose(r.odometry_zxphi).inverse(),
		                      "world", "odom", t));
	}
	if (r.true_zxphi)
	{
		geometry_msgs::PoseStamped p;
		p.header.stamp = toRosTime(t);
		p.header.frame_id = "world";
		p.pose = toPoseMsg(planarPose(*r.true_zxphi));
		out.write("/ground_truth/pose", t, p);
	}
}
}  // namespace

BagSummary rawlogToBag(const std::string& rawlog, const std::string& bag,
                       const std::function<void(size_t, size_t)>& progress)
{
	const auto records = io::readRawlog(rawlog, io::ImageLoading::Paths);
	BagOut out(bag);
	const bool estimated = std::any_of(records.begin(), records.end(),
	                                   [](const io::RawlogRecord& r) { return r.estimate_zxphi.has_value(); });
	if (!records.empty() && !estimated)  // no estimate: world and odom stay together
		out.tf(toTransformMsg(Eigen::Isometry3d::Identity(), "world", "odom", records.front().time_s),
		       "/tf_static");
	for (size_t i = 0; i < records.size(); ++i)
	{
		const auto& r = records[i];
		r.has_stereo ? writePair(r, out) : writeState(r, out);
		++out.summary.records;
		if (progress) progress(i + 1, records.size());
	}
	return out.summary;
}

}  // namespace mrolr::ros
