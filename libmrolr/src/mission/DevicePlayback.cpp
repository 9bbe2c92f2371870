// Playback devices: every request is matched with the next recorded call and answered from it.
#include <mrolr/mission/DevicePlayback.h>

#include <cstring>
#include <sstream>

namespace mrolr::mission
{
struct DevicePlayback::Impl
{
	explicit Impl(const std::string& path) : rec(readDeviceCalls(path)) {}
	RecordedCalls rec;
	size_t next = 0, next_stop = 0;
	std::atomic<bool> stop{false};
	std::unique_ptr<hw::BaseDevice> base;
	std::unique_ptr<hw::HeadDevice> head;
	std::unique_ptr<hw::ArmDevice> arm;

	static bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
	{
		return a.size() == b.size() &&
		       (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
	}

	[[noreturn]] void diverge(CallKind kind, const std::vector<double>& request) const
	{
		std::ostringstream s;
		s << "replay diverged at device call " << next << " of " << rec.calls.size() << ": the robot asked "
		  << describe(kind, request);
		if (next < rec.calls.size())
		{
			const auto& c = rec.calls[next];
			s << " at device time " << c.time_s << " s, where the recording has "
			  << describe(c.kind, c.request);
		}
		else
			s << " after the recording's last call" << (rec.torn.empty() ? "" : " (" + rec.torn + ")");
		throw hw::ReplayDivergence(s.str());
	}

	/** The recorded answer to @p kind(@p request), or its fault thrown. */
	const DeviceCall& serve(CallKind kind, const std::vector<double>& request)
	{
		while (next_stop < rec.stops_before.size() && rec.stops_before[next_stop] <= next)
		{
			stop = true;  // the recorded run raised its stop flag here
			++next_stop;
		}
		if (next >= rec.calls.size() || rec.calls[next].kind != kind ||
		    !sameBits(rec.calls[next].request, request))
			diverge(kind, request);
		const auto& c = rec.calls[next++];
		if (c.fault) rethrow(*c.fault);
		return c;
	}
};

namespace
{
using Impl = DevicePlayback::Impl;

class PlaybackBase : public hw::BaseDevice
{
 public:
	explicit PlaybackBase(Impl& p) : p_(p) {}
	void step(const base::WheelControl& u) override
	{
		p_.serve(CallKind::BaseStep, {u.v1_mps, u.v2_mps, u.dt_s});
	}
	hw::Odometry odometry() const override
	{
		const auto& a = p_.serve(CallKind::BaseOdometry, {}).answer;
		hw::Odometry o;
		o.xv_zxphi = {a[0], a[1], a[2]};
		o.ticks_right = static_cast<long>(a[3]);
		o.ticks_left = static_cast<long>(a[4]);
		o.time_s = a[5];
		o.bumper = a[6] != 0;
		return o;
	}

 private:
	Impl& p_;
};

class PlaybackHead : public hw::HeadDevice
{
 public:
	explicit PlaybackHead(Impl& p) : p_(p) {}
	double moveTo(const geometry::HeadAngles& target) override
	{
		return p_.serve(CallKind::HeadMove, valuesOf(target)).answer[0];
	}
	geometry::HeadAngles angles() const override
	{
		return anglesFrom(p_.serve(CallKind::HeadAngles, {}).answer);
	}
	hw::StereoImages grab() override
	{
		return loadPair(*p_.serve(CallKind::HeadGrab, {}).images, p_.rec.path);
	}

 private:
	Impl& p_;
};

class PlaybackArm : public hw::ArmDevice
{
 public:
	explicit PlaybackArm(Impl& p) : p_(p) {}
	void moveTo(const hw::ArmJoints& j) override
	{
		p_.serve(CallKind::ArmMove, {j.begin(), j.end()});
	}
	hw::ArmJoints joints() const override
	{
		const auto& a = p_.serve(CallKind::ArmJoints, {}).answer;
		hw::ArmJoints j{};
		std::copy(a.begin(), a.end(), j.begin());
		return j;
	}
	void setGripper(bool closed) override { p_.serve(CallKind::ArmGripper, {closed ? 1.0 : 0.0}); }
	bool gripperClosed() const override
	{
		return p_.serve(CallKind::ArmGripperClosed, {}).answer[0] != 0;
	}
	double gripperWidthMm() const override
	{
		return p_.serve(CallKind::ArmGripperWidth, {}).answer[0];
	}
	void dock(bool docked) override { p_.serve(CallKind::ArmDock, {docked ? 1.0 : 0.0}); }
	bool docked() const override { return p_.serve(CallKind::ArmDocked, {}).answer[0] != 0; }

 private:
	Impl& p_;
};
}  // namespace

DevicePlayback::DevicePlayback(const std::string& rawlog_path)
    : impl_(std::make_unique<Impl>(rawlog_path))
{
	impl_->base = std::make_unique<PlaybackBase>(*impl_);
	impl_->head = std::make_unique<PlaybackHead>(*impl_);
	impl_->arm = std::make_unique<PlaybackArm>(*impl_);
}

DevicePlayback::~DevicePlayback() = default;

RobotDevices DevicePlayback::devices()
{
	return {impl_->base.get(), impl_->head.get(), impl_->arm.get(), {}};
}

std::atomic<bool>& DevicePlayback::stopFlag()
{
	return impl_->stop;
}

size_t DevicePlayback::served() const
{
	return impl_->next;
}

size_t DevicePlayback::recorded() const
{
	return impl_->rec.calls.size();
}

const std::string& DevicePlayback::torn() const
{
	return impl_->rec.torn;
}

}  // namespace mrolr::mission
