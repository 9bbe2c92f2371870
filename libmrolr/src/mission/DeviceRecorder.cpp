// Recording devices: each call goes to the device, then (answer or fault) into mission.rawlog.
#include "DeviceRecorderImpl.h"

namespace mrolr::mission
{
namespace
{
using Impl = DeviceRecorder::Impl;
/** Pairs kept for the decisions' pictures: a whole sweep's views. */
constexpr size_t kRecentPairs = 32;

/** @p p with pixels of its own. */
hw::StereoImages deepCopy(hw::StereoImages p)
{
	p.left = p.left.makeDeepCopy();
	p.right = p.right.makeDeepCopy();
	return p;
}

/** A request of @p kind with @p values, its answer still to come. */
DeviceCall request(CallKind kind, std::vector<double> values = {})
{
	DeviceCall c;
	c.kind = kind;
	c.request = std::move(values);
	return c;
}

/** A reading of one value through @p r, recorded as a number. */
template <typename F>
auto readNumber(Impl& r, CallKind kind, F&& read)
{
	auto c = request(kind);
	decltype(read()) v{};
	r.call(c,
	       [&]
	       {
		       v = read();
		       c.answer = {double(v)};
	       });
	return v;
}

class RecordingBase : public hw::BaseDevice
{
 public:
	explicit RecordingBase(Impl& r) : r_(r) {}
	void step(const base::WheelControl& u) override
	{
		auto c = request(CallKind::BaseStep, {u.v1_mps, u.v2_mps, u.dt_s});
		r_.call(c, [&] { r_.dev.base->step(u); });
		if (*r_.world_truth)
			if (auto truth = (*r_.world_truth)()) r_.post(std::move(truth));
	}
	hw::Odometry odometry() const override
	{
		auto c = request(CallKind::BaseOdometry);
		hw::Odometry o;
		r_.call(c,
		        [&]
		        {
			        o = r_.dev.base->odometry();
			        r_.clock_s = std::max(r_.clock_s, o.time_s);
			        c.answer = {o.xv_zxphi[0],        o.xv_zxphi[1],       o.xv_zxphi[2],
			                    double(o.ticks_right), double(o.ticks_left), o.time_s,
			                    o.bumper ? 1.0 : 0.0};
		        });
		r_.odometryObservations(o);
		return o;
	}

 private:
	Impl& r_;
};

class RecordingHead : public hw::HeadDevice
{
 public:
	explicit RecordingHead(Impl& r) : r_(r) {}
	double moveTo(const geometry::HeadAngles& target) override
	{
		auto c = request(CallKind::HeadMove, valuesOf(target));
		double settle = 0;
		r_.call(c,
		        [&]
		        {
			        settle = r_.dev.head->moveTo(target);
			        c.answer = {settle};
		        });
		return settle;
	}
	geometry::HeadAngles angles() const override
	{
		auto c = request(CallKind::HeadAngles);
		geometry::HeadAngles a;
		r_.call(c,
		        [&]
		        {
			        a = r_.dev.head->angles();
			        c.answer = valuesOf(a);
		        });
		return a;
	}
	hw::StereoImages grab() override
	{
		auto c = request(CallKind::HeadGrab);
		hw::StereoImages p;
		r_.call(c,
		        [&]
		        {
			        p = r_.dev.head->grab();
			        r_.clock_s = std::max(r_.clock_s, p.time_s);
			        c.answer = valuesOf(p.angles);
			        c.answer.insert(c.answer.end(), {p.time_s, double(p.frame)});
			        c.images = deepCopy(p);  // the writer thread's own pixels
		        });
		r_.recent.push_back(*c.images);
		if (r_.recent.size() > kRecentPairs) r_.recent.pop_front();
		return p;
	}

 private:
	Impl& r_;
};

class RecordingArm : public hw::ArmDevice
{
 public:
	explicit RecordingArm(Impl& r) : r_(r) {}
	void moveTo(const hw::ArmJoints& j) override
	{
		auto c = request(CallKind::ArmMove, {j.begin(), j.end()});
		r_.call(c, [&] { r_.dev.arm->moveTo(j); });
	}
	hw::ArmJoints joints() const override
	{
		auto c = request(CallKind::ArmJoints);
		hw::ArmJoints j{};
		r_.call(c,
		        [&]
		        {
			        j = r_.dev.arm->joints();
			        c.answer.assign(j.begin(), j.end());
		        });
		return j;
	}
	void setGripper(bool closed) override
	{
		auto c = request(CallKind::ArmGripper, {closed ? 1.0 : 0.0});
		r_.call(c, [&] { r_.dev.arm->setGripper(closed); });
	}
	bool gripperClosed() const override
	{
		return readNumber(r_, CallKind::ArmGripperClosed, [this] { return r_.dev.arm->gripperClosed(); });
	}
	double gripperWidthMm() const override
	{
		return readNumber(r_, CallKind::ArmGripperWidth, [this] { return r_.dev.arm->gripperWidthMm(); });
	}
	void dock(bool docked) override
	{
		auto c = request(CallKind::ArmDock, {docked ? 1.0 : 0.0});
		r_.call(c, [&] { r_.dev.arm->dock(docked); });
	}
	bool docked() const override
	{
		return readNumber(r_, CallKind::ArmDocked, [this] { return r_.dev.arm->docked(); });
	}

 private:
	Impl& r_;
};
}  // namespace

DeviceRecorder::DeviceRecorder(const std::string& rawlog_path, RobotDevices devices,
                               const geometry::BiSightHead& head)
    : impl_(std::make_unique<Impl>(rawlog_path, std::move(devices), head))
{
	if (!impl_->dev.base || !impl_->dev.head || !impl_->dev.arm)
		throw std::invalid_argument("DeviceRecorder: every device (base, head, arm) must be given");
	impl_->world_truth = &world_truth;
	impl_->base = std::make_unique<RecordingBase>(*impl_);
	impl_->head_device = std::make_unique<RecordingHead>(*impl_);
	impl_->arm = std::make_unique<RecordingArm>(*impl_);
}

DeviceRecorder::~DeviceRecorder() = default;

RobotDevices DeviceRecorder::devices()
{
	return {impl_->base.get(), impl_->head_device.get(), impl_->arm.get(), impl_->dev.links};
}

std::atomic<bool>& DeviceRecorder::stopFlag(std::atomic<bool>* signal)
{
	impl_->signal = signal;
	return impl_->gate;
}

void DeviceRecorder::write(mrpt::obs::CObservation::Ptr obs)
{
	if (obs) impl_->post(std::move(obs));
}

void DeviceRecorder::flush()
{
	impl_->log.flush();
}

io::ObservationQueue::Stats DeviceRecorder::stats()
{
	return impl_->log.stats();
}

size_t DeviceRecorder::calls() const
{
	return impl_->calls;
}

}  // namespace mrolr::mission
