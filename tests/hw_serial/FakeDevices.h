#pragma once
// Minimal recording devices for the protocol tests: they remember what they were asked and refuse
// limits as the interfaces document.
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw/Devices.h>

#include <stdexcept>
#include <vector>

namespace fake
{
struct Base : mrolr::hw::BaseDevice
{
	std::vector<mrolr::base::WheelControl> steps;
	mrolr::hw::Odometry odo;
	void step(const mrolr::base::WheelControl& u) override
	{
		steps.push_back(u);
		odo.ticks_right += 10, odo.ticks_left -= 3, odo.time_s += u.dt_s;
		odo.xv_zxphi[0] += u.v1_mps * u.dt_s;
	}
	mrolr::hw::Odometry odometry() const override { return odo; }
};

struct Head : mrolr::hw::HeadDevice
{
	mrolr::geometry::HeadAngles a;
	int moves = 0;
	double moveTo(const mrolr::geometry::HeadAngles& t) override
	{
		if (std::abs(t.pan) > 3) throw mrolr::geometry::FixationError("pan beyond its limit");
		a = t;
		++moves;
		return 0.5;
	}
	mrolr::geometry::HeadAngles angles() const override { return a; }
	mrolr::hw::StereoImages grab() override { return {}; }
};

struct Arm : mrolr::hw::ArmDevice
{
	mrolr::hw::ArmJoints j{};
	bool closed = false;
	void moveTo(const mrolr::hw::ArmJoints& t) override
	{
		if (t[0] < 0) throw std::out_of_range("arm joint d1_mm = -1 outside [0, 915]");
		if (t[0] > 910) throw mrolr::hw::ArmBlocked("the gripper met table 'main'");
		j = t;
	}
	mrolr::hw::ArmJoints joints() const override { return j; }
	void setGripper(bool c) override { closed = c; }
	bool gripperClosed() const override { return closed; }
	double gripperWidthMm() const override { return closed ? 0 : 90; }
	bool is_docked = false;
	void dock(bool d) override
	{
		if (!d && closed) throw std::logic_error("the arm holds something");
		is_docked = d;
	}
	bool docked() const override { return is_docked; }
};
}  // namespace fake
