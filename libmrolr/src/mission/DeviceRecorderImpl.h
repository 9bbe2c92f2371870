#pragma once
// The state behind DeviceRecorder, shared by its device decorators and its decision writers.
#include <mrolr/geometry/Frames.h>
#include <mrolr/io/ObservationQueue.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/DeviceRecorder.h>

#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>

#include <deque>

namespace mrolr::mission
{
struct DeviceRecorder::Impl
{
	Impl(const std::string& path, RobotDevices d, const geometry::BiSightHead& h)
	    : log(path), dev(std::move(d)), head(h)
	{
	}
	io::ObservationQueue log;  ///< the writer thread: images encoded and records written there
	RobotDevices dev;
	geometry::BiSightHead head;
	size_t calls = 0, pictures = 0;
	double clock_s = 0;  ///< the latest of the devices' clocks (odometry, grabs): the records' time
	bool bumper = false;
	std::deque<hw::StereoImages> recent;  ///< the latest pairs, for the decisions' pictures
	std::atomic<bool> gate{false};
	std::atomic<bool>* signal = nullptr;
	std::function<mrpt::obs::CObservation::Ptr()>* world_truth = nullptr;
	std::unique_ptr<hw::BaseDevice> base;
	std::unique_ptr<hw::HeadDevice> head_device;
	std::unique_ptr<hw::ArmDevice> arm;

	mrpt::Clock::time_point stamp() const { return io::stampOf(clock_s); }

	/** Queues @p obs for the writer thread. */
	void post(mrpt::obs::CObservation::Ptr obs)
	{
		log.post([obs](io::ObservationLogWriter& w) { w.write(*obs); });
	}

	/** A stop requested since the last call is raised now, and marked before this call. */
	void checkStop()
	{
		if (!signal || !signal->load() || gate.load()) return;
		post(io::labelledComment(
		    kStopLabel, "stop requested (signal): the mission stops before its next motion",
		    stamp()));
		gate = true;
	}

	/** Queues the call's records; its pair's images are encoded by the writer thread. */
	void write(DeviceCall& c)
	{
		c.time_s = clock_s;
		log.post([c, index = calls, h = head](io::ObservationLogWriter& w)
		         { for (const auto& obs : observationsOf(c, index, h, w)) w.write(*obs); });
		++calls;
	}

	/** Runs @p forward (the device call, filling c.answer) and records it, or its fault. */
	template <typename F>
	void call(DeviceCall& c, F&& forward)
	{
		checkStop();
		try
		{
			forward();
		}
		catch (const std::exception& e)
		{
			c.fault = faultOf(e);
			c.answer.clear();
			write(c);
			throw;
		}
		write(c);
	}

	void odometryObservations(const hw::Odometry& o)
	{
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = stamp();
		odo->odometry = geometry::vehicleToMrpt(o.xv_zxphi);
		odo->hasEncodersInfo = true;
		odo->encoderRightTicks = int32_t(o.ticks_right);
		odo->encoderLeftTicks = int32_t(o.ticks_left);
		post(odo);
		if (o.bumper && !bumper)
		{
			auto b = mrpt::obs::CObservationRawDAQ::Create();
			b->sensorLabel = "BUMPER";
			b->timestamp = stamp();
			b->DIN = {1};
			post(b);
		}
		bumper = o.bumper;
	}
};

}  // namespace mrolr::mission
