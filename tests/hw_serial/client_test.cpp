// The serial client and drivers against an in-memory stream (the port swapped for a pipe, as in
// MRPT's CGPSInterface_unittest): exact request bytes, split replies, stale replies, retries,
// timeouts, garbage and disconnects.
#include "ExpectSerialError.h"
#include "FakeDevices.h"
#include "ScriptedPeer.h"

#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/SerialDrivers.h>

#include <gtest/gtest.h>

using namespace mrolr;
using namespace mrolr::hw;
using namespace mrolr::hw_serial;
using Kind = SerialDeviceError::Kind;

namespace
{
LinkOptions fastLink(int retries = 2)
{
	LinkOptions o;
	o.device = "device.test";
	o.timeout_ms = 100;
	o.retries = retries;
	o.first_seq = 1;  // the scripts answer numbers from 1
	return o;
}

std::string f(const std::string& body)
{
	return frameLine(body);
}

}  // namespace

TEST(SerialClient, BaseDriverSendsExactBytesAndReadsOdometry)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(
	    std::move(dev),
	    {{f("1 OK LABMATE 1")}, {f("2 OK")}, {f("3 OK 0.5 -0.25 0.125 10000 9990 2.5 1")}});
	SerialBase base(std::make_unique<SerialClient>(std::move(host), fastLink()));
	base.step({0.2, -0.1, 0.5});
	const Odometry o = base.odometry();
	const auto requests = peer.requests(3);
	ASSERT_EQ(requests.size(), 3u);
	EXPECT_EQ(requests[0], "1 ID?*614B2F7B\n");
	EXPECT_EQ(requests[1], f("2 STEP 0.2 -0.1 0.5"));
	EXPECT_EQ(requests[2], f("3 ODO?"));
	EXPECT_EQ(o.xv_zxphi, Eigen::Vector3d(0.5, -0.25, 0.125));
	EXPECT_EQ(o.ticks_right, 10000);
	EXPECT_EQ(o.ticks_left, 9990);
	EXPECT_EQ(o.time_s, 2.5);
	EXPECT_TRUE(o.bumper);
}

TEST(SerialClient, RepliesArrivingInPiecesAreReassembled)
{
	auto [host, dev] = makeMemoryPipe();
	const std::string r = f("1 OK RTX 1") + f("2 OK 1 2 3 4 5 6 7");
	std::vector<std::string> pieces1, pieces2;
	const size_t cut = r.find('\n') + 1;
	for (size_t i = 0; i < cut; i += 3)
		pieces1.push_back(r.substr(i, std::min<size_t>(3, cut - i)));
	for (size_t i = cut; i < r.size(); i += 5) pieces2.push_back(r.substr(i, 5));
	ScriptedPeer peer(std::move(dev), {pieces1, pieces2}, 2);
	SerialArm arm(std::make_unique<SerialClient>(std::move(host), fastLink()));
	EXPECT_EQ(arm.joints(), (ArmJoints{1, 2, 3, 4, 5, 6, 7}));
}

TEST(SerialClient, StaleRepliesWithAnotherSequenceNumberAreSkipped)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(std::move(dev),
	                  {{f("1 OK BISIGHT 1")}, {f("1 OK BISIGHT 1"), f("2 OK 0.1 0.2 0.3 0.4")}});
	SerialHead head(std::make_unique<SerialClient>(std::move(host), fastLink()), nullptr);
	const auto a = head.angles();
	EXPECT_EQ(a.pan, 0.1);
	EXPECT_EQ(a.verg_right, 0.4);
}

TEST(SerialClient, ASilentDeviceTimesOutAfterTheRetriesNamingDeviceAndPort)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(std::move(dev), {});
	SerialClient client(std::move(host), fastLink(2));
	const auto e = expectSerialError([&] { client.call("ODO?", {}); });
	EXPECT_EQ(e.kind(), Kind::Timeout);
	EXPECT_STREQ(
	    e.what(),
	    "device.test on memory: timeout: no reply after 3 attempts of 100 ms (command ODO?)");
	const auto requests = peer.requests(3);
	ASSERT_EQ(requests.size(), 3u);
	EXPECT_EQ(requests[0], requests[2]);  // resent with the same sequence number
	EXPECT_EQ(client.resends(), 2);
}

TEST(SerialClient, SequenceNumbersStartAtRandomAndWrapAfter9999)
{
	auto [host1, dev1] = makeMemoryPipe();
	auto [host2, dev2] = makeMemoryPipe();
	LinkOptions random_start = fastLink(0);
	random_start.first_seq = 0;
	random_start.timeout_ms = 1;
	SerialClient a(std::move(host1), random_start), b(std::move(host2), random_start);
	EXPECT_THROW(a.call("ODO?", {}), SerialDeviceError);
	EXPECT_THROW(b.call("ODO?", {}), SerialDeviceError);
	const std::string ra = dev1->read(100), rb = dev2->read(100);
	EXPECT_NE(ra, rb);  // two hosts start at different numbers (1 chance in 9999 to collide)

	auto [host, dev] = makeMemoryPipe();
	LinkOptions last = fastLink(0);
	last.first_seq = 9999;
	ScriptedPeer peer(std::move(dev), {{f("9999 OK 0")}, {f("1 OK 1")}});
	SerialClient c(std::move(host), last);
	EXPECT_EQ(c.call("GRIP?", {}), std::vector<std::string>{"0"});
	EXPECT_EQ(c.call("GRIP?", {}), std::vector<std::string>{"1"});
}

TEST(SerialClient, GarbageIsRetriedThenReportedWithItsBytes)
{
	auto [host, dev] = makeMemoryPipe();
	const std::string junk("\x13\xff noise\n", 9);
	ScriptedPeer peer(std::move(dev), {{junk}, {junk}, {junk}});
	SerialClient client(std::move(host), fastLink(2));
	const auto e = expectSerialError([&] { client.call("JNT?", {}); });
	EXPECT_EQ(e.kind(), Kind::Garbage);
	EXPECT_NE(std::string(e.what()).find("garbage reply '\\x13\\xFF noise'"), std::string::npos)
	    << e.what();
	EXPECT_EQ(peer.requests(3).size(), 3u);
}

TEST(SerialClient, OneDamagedReplyIsRetriedAndSucceeds)
{
	auto [host, dev] = makeMemoryPipe();
	std::string damaged = f("1 OK 1");
	damaged.erase(3, 1);
	ScriptedPeer peer(std::move(dev),
	                  {{damaged}, {f("- ERR BADLINE checksum mismatch")}, {f("1 OK 1")}});
	SerialClient client(std::move(host), fastLink(2));
	EXPECT_EQ(client.call("GRIP?", {}), std::vector<std::string>{"1"});
	EXPECT_EQ(client.resends(), 2);
}

TEST(SerialClient, OverlongRepliesAreGarbage)
{
	auto [host, dev] = makeMemoryPipe();
	const std::string flood(5000, 'A');
	ScriptedPeer peer(std::move(dev), {{flood + "\n"}});
	SerialClient client(std::move(host), fastLink(0));
	const auto e = expectSerialError([&] { client.call("ODO?", {}); });
	EXPECT_EQ(e.kind(), Kind::Garbage);
	EXPECT_NE(std::string(e.what()).find("overlong reply 'AAAA"), std::string::npos) << e.what();
}

TEST(SerialClient, ADisconnectIsReportedAtOnce)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(std::move(dev), {});
	peer.close();
	SerialClient client(std::move(host), fastLink(5));
	const auto e = expectSerialError([&] { client.call("ODO?", {}); });
	EXPECT_EQ(e.kind(), Kind::Disconnected);
	EXPECT_NE(std::string(e.what()).find("device.test on memory: disconnected"), std::string::npos);
}

TEST(SerialClient, MalformedReplyFieldsAreReportedAsGarbage)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(std::move(dev), {{f("1 OK LABMATE 1")}, {f("2 OK 1 2 3 4.5 6 7 0")}});
	SerialBase base(std::make_unique<SerialClient>(std::move(host), fastLink()));
	const auto e = expectSerialError([&] { base.odometry(); });
	EXPECT_EQ(e.kind(), Kind::Garbage);
	EXPECT_NE(std::string(e.what()).find("ticks_r: '4.5' is not an integer"), std::string::npos)
	    << e.what();
}

TEST(SerialClient, ABumperFieldOtherThanZeroOrOneIsGarbage)
{
	auto [host, dev] = makeMemoryPipe();
	ScriptedPeer peer(std::move(dev), {{f("1 OK LABMATE 1")}, {f("2 OK 1 2 3 4 6 7 yes")}});
	SerialBase base(std::make_unique<SerialClient>(std::move(host), fastLink()));
	const auto e = expectSerialError([&] { base.odometry(); });
	EXPECT_EQ(e.kind(), Kind::Garbage);
	EXPECT_NE(std::string(e.what()).find("bumper"), std::string::npos) << e.what();
}

TEST(SerialDrivers, RefuseAnotherDeviceOnThePort)
{
	auto [host, dev] = makeMemoryPipe();
	fake::Arm arm;
	ArmHandler handler(arm);
	DeviceEmulator emulator(*dev, handler);
	const auto e = expectSerialError(
	    [&] { SerialBase base(std::make_unique<SerialClient>(std::move(host), fastLink())); });
	EXPECT_EQ(e.kind(), Kind::Refused);
	EXPECT_NE(std::string(e.what()).find("expected a LABMATE but the device answered ID 'RTX'"),
	          std::string::npos);
}

TEST(SerialDrivers, LimitRefusalsBecomeTheInterfacesExceptions)
{
	auto [host_h, dev_h] = makeMemoryPipe();
	auto [host_a, dev_a] = makeMemoryPipe();
	fake::Head head;
	fake::Arm arm;
	HeadHandler hh(head);
	ArmHandler ah(arm);
	DeviceEmulator eh(*dev_h, hh), ea(*dev_a, ah);
	SerialHead shead(std::make_unique<SerialClient>(std::move(host_h), fastLink()), nullptr);
	SerialArm sarm(std::make_unique<SerialClient>(std::move(host_a), fastLink()));
	EXPECT_THROW(shead.moveTo({4, 0, 0, 0}), geometry::FixationError);
	EXPECT_THROW(sarm.moveTo({-1, 0, 0, 0, 0, 0, 0}), std::out_of_range);
	EXPECT_THROW(sarm.moveTo({911, 0, 0, 0, 0, 0, 0}), hw::ArmBlocked);  // ERR BLOCKED
	EXPECT_THROW(shead.grab(), std::logic_error);  // no image source
	EXPECT_DOUBLE_EQ(shead.moveTo({0.1, 0, 0, 0}), 0.5);
	EXPECT_DOUBLE_EQ(sarm.gripperWidthMm(), 90);
	sarm.setGripper(true);
	EXPECT_TRUE(sarm.gripperClosed());
	EXPECT_DOUBLE_EQ(sarm.gripperWidthMm(), 0);
	EXPECT_TRUE(arm.closed);
}

TEST(SerialDrivers, HeadGrabStampsTheInjectedImagesWithTheHeadAngles)
{
	auto [host, dev] = makeMemoryPipe();
	fake::Head head;
	HeadHandler handler(head);
	DeviceEmulator emulator(*dev, handler);
	int grabs = 0;
	SerialHead shead(std::make_unique<SerialClient>(std::move(host), fastLink()),
	                 [&]
	                 {
		                 ++grabs;
		                 StereoImages s;
		                 s.left = mrpt::img::CImage(8, 6, mrpt::img::CH_GRAY);
		                 s.time_s = 3.5;
		                 return s;
	                 });
	shead.moveTo({0.2, -0.1, 0.03, -0.03});
	const auto s = shead.grab();
	EXPECT_EQ(grabs, 1);
	EXPECT_EQ(s.left.getWidth(), 8u);
	EXPECT_EQ(s.time_s, 3.5);
	EXPECT_EQ(s.angles.pan, 0.2);
	EXPECT_EQ(s.angles.verg_right, -0.03);
}

TEST(SerialDrivers, AStepWaitsForItsDurationOnTopOfTheTimeout)
{
	auto [host, dev] = makeMemoryPipe();
	// the device answers a 0.5 s step after 250 ms + 250 ms: beyond the 300 ms timeout, within
	// 300 + 500
	ScriptedPeer peer(std::move(dev), {{f("1 OK LABMATE 1")}, {"", f("2 OK")}}, 250);
	LinkOptions link = fastLink(0);
	link.timeout_ms = 300;  // the identification answers after 250 ms too
	SerialBase base(std::make_unique<SerialClient>(std::move(host), link));
	EXPECT_NO_THROW(base.step({0.1, 0.1, 0.5}));
	EXPECT_EQ(peer.requests(2).size(), 2u);
}
