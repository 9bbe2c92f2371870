// The camera socket on loopback: CameraServer and CameraSocketClient against each other, and the
// client against peers that misbehave (garbage, silence, replies to another request).
#include "CameraTestUtil.h"
#include "ExpectSerialError.h"

#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/hw_serial/CameraWire.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace mrolr;
using Kind = hw_serial::SerialDeviceError::Kind;
using camtest::noisePair;
using camtest::sameGreyPixels;

namespace
{
constexpr int kTimeoutMs = 1000;

double secondsSince(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/** The error names the device section and the address, in its fields and its text. */
void expectNamed(const hw_serial::SerialDeviceError& e, const std::string& address)
{
	EXPECT_EQ(e.device(), "device.camera");
	EXPECT_EQ(e.port(), address);
	EXPECT_NE(std::string(e.what()).find("device.camera on " + address), std::string::npos)
	    << e.what();
}

/** A peer that answers every request with @p reply(request bytes). */
camtest::ScriptedCameraPeer answering(std::function<std::string(const std::string&)> reply)
{
	return camtest::ScriptedCameraPeer(
	    [reply](auto& c, const auto& stop)
	    {
		    std::string request;
		    while (camtest::readRequest(c, stop, request))
		    {
			    hw_serial::writeAll(c, reply(request), hw_serial::deadlineIn(2000), &stop);
			    request.clear();
		    }
		    camtest::holdSilently(c, stop);
	    });
}

uint32_t seqOf(const std::string& request)
{
	return hw_serial::decodeCameraHeader(request).seq;
}
}  // namespace

TEST(CameraSocket, RoundTripGivesBitIdenticalImagesTimeAndAngles)
{
	const hw::StereoImages sent = noisePair(640, 480, 7);
	hw_serial::CameraServer server([&] { return sent; });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	const hw::StereoImages got = client.grab();
	EXPECT_TRUE(sameGreyPixels(got.left, sent.left));
	EXPECT_TRUE(sameGreyPixels(got.right, sent.right));
	EXPECT_FALSE(sameGreyPixels(got.left, got.right));
	EXPECT_EQ(got.time_s, sent.time_s);
	EXPECT_EQ(got.angles.pan, sent.angles.pan);
	EXPECT_EQ(got.angles.tilt, sent.angles.tilt);
	EXPECT_EQ(got.angles.verg_left, sent.angles.verg_left);
	EXPECT_EQ(got.angles.verg_right, sent.angles.verg_right);
	EXPECT_EQ(server.served(), 1u);
}

TEST(CameraSocket, ConsecutiveGrabsEachGetAFreshPair)
{
	unsigned calls = 0;
	hw_serial::CameraServer server([&] { return noisePair(64, 48, ++calls); });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	const auto first = client.grab();
	const auto second = client.grab();
	EXPECT_TRUE(sameGreyPixels(first.left, noisePair(64, 48, 1).left));
	EXPECT_TRUE(sameGreyPixels(second.left, noisePair(64, 48, 2).left));
	EXPECT_EQ(second.time_s, noisePair(64, 48, 2).time_s);
	EXPECT_EQ(calls, 2u);
	EXPECT_EQ(server.accepted(), 1u);  // both on one connection
}

TEST(CameraSocket, ServerStoppedMidRunIsADisconnectNamingDeviceAndAddress)
{
	hw_serial::CameraServer server([] { return noisePair(32, 24, 1); });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	client.grab();
	server.stop();
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	expectNamed(e, server.address());
	// the next grab tries to connect again, and nothing listens any more
	const auto again = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(again.kind(), Kind::Disconnected) << again.what();
	expectNamed(again, server.address());
}

TEST(CameraSocket, NothingListeningIsADisconnectFromTheConstructor)
{
	const std::string address = "127.0.0.1:" + std::to_string(hw_serial::freeLoopbackPort());
	const auto e = expectSerialError([&] { hw_serial::CameraSocketClient c(address, kTimeoutMs); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	expectNamed(e, address);
	EXPECT_NE(std::string(e.what()).find("cannot connect"), std::string::npos) << e.what();
}

TEST(CameraSocket, GarbageFromThePeerIsGarbage)
{
	auto peer =
	    answering([](const std::string&) { return std::string("\x13\xFFnot a frame\x80", 14); });
	hw_serial::CameraSocketClient client(peer.address(), kTimeoutMs);
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Garbage) << e.what();
	expectNamed(e, peer.address());
}

TEST(CameraSocket, AnImagesFrameThatDoesNotDeserializeIsGarbage)
{
	auto peer = answering(
	    [](const std::string& request)
	    {
		    const std::string junk(300, '\x5A');
		    return hw_serial::encodeCameraHeader({hw_serial::CameraFrameKind::Images, seqOf(request), 300}) +
		           junk;
	    });
	hw_serial::CameraSocketClient client(peer.address(), kTimeoutMs);
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Garbage) << e.what();
	expectNamed(e, peer.address());
}

TEST(CameraSocket, AReplyToAnotherRequestIsGarbage)
{
	auto peer =
	    answering([](const std::string& request)
	              { return hw_serial::encodeCameraImages(seqOf(request) + 1, noisePair(8, 8, 1)); });
	hw_serial::CameraSocketClient client(peer.address(), kTimeoutMs);
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Garbage) << e.what();
	EXPECT_NE(std::string(e.what()).find("reply to request"), std::string::npos) << e.what();
}

TEST(CameraSocket, APeerThatNeverAnswersTimesOutAfterAboutTheTimeout)
{
	camtest::ScriptedCameraPeer peer(camtest::holdSilently);
	hw_serial::CameraSocketClient client(peer.address(), 300);
	const auto t0 = std::chrono::steady_clock::now();
	const auto e = expectSerialError([&] { client.grab(); });
	const double waited_s = secondsSince(t0);
	EXPECT_EQ(e.kind(), Kind::Timeout) << e.what();
	expectNamed(e, peer.address());
	EXPECT_GE(waited_s, 0.3);
	EXPECT_LT(waited_s, 1.3);  // a bound against hanging, not a timing target
}

TEST(CameraSocket, AGrabThatFailsIsRefusedWithItsMessageAndTheServerGoesOn)
{
	int calls = 0;
	hw_serial::CameraServer server(
	    [&]
	    {
		    if (++calls == 1) throw std::runtime_error("frame grabber lost sync");
		    return noisePair(16, 12, 3);
	    });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Refused) << e.what();
	EXPECT_NE(std::string(e.what()).find("frame grabber lost sync"), std::string::npos);
	EXPECT_TRUE(sameGreyPixels(client.grab().left, noisePair(16, 12, 3).left));
}

TEST(CameraSocket, ALateReplyIsNeverTakenForTheNextOne)
{
	// the first grab takes longer than the timeout; the client gives up on that connection
	int calls = 0;
	hw_serial::CameraServer server(
	    [&]
	    {
		    if (++calls == 1) std::this_thread::sleep_for(std::chrono::milliseconds(800));
		    return noisePair(16, 12, unsigned(calls));
	    });
	hw_serial::CameraSocketClient client(server.address(), 600);
	EXPECT_EQ(expectSerialError([&] { client.grab(); }).kind(), Kind::Timeout);
	const auto second = client.grab();
	EXPECT_TRUE(sameGreyPixels(second.left, noisePair(16, 12, 2).left));
	EXPECT_EQ(server.accepted(), 2u);
}

TEST(CameraSocket, ClientsThatHangUpOrSendGarbageDoNotStopTheServer)
{
	hw_serial::CameraServer server([] { return noisePair(320, 240, 5); });
	{
		// asks for a pair and leaves without reading it
		mrpt::comms::CClientTCPSocket rude;
		rude.connect("127.0.0.1", server.port(), 1000);
		hw_serial::writeAll(rude, hw_serial::encodeCameraRequest(1), hw_serial::deadlineIn(1000));
	}
	{
		mrpt::comms::CClientTCPSocket noisy;
		noisy.connect("127.0.0.1", server.port(), 1000);
		hw_serial::writeAll(noisy, "GET / HTTP/1.0\r\n\r\n", hw_serial::deadlineIn(1000));
		std::string rest;
		// the server hangs up on it
		EXPECT_EQ(hw_serial::readExact(noisy, 1, rest, hw_serial::deadlineIn(2000)), hw_serial::SocketIoStatus::Closed);
	}
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	EXPECT_TRUE(sameGreyPixels(client.grab().right, noisePair(320, 240, 5).right));
	EXPECT_EQ(server.rejected(), 1u);
}

TEST(CameraSocket, StopReturnsPromptlyWithAnIdleClientConnected)
{
	hw_serial::CameraServer server([] { return noisePair(8, 8, 1); });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	client.grab();
	const auto t0 = std::chrono::steady_clock::now();
	server.stop();
	EXPECT_LT(secondsSince(t0), 1.0);  // a bound against hanging, not a timing target
}

TEST(CameraSocket, AGivenPortIsUsedAndATakenOneIsRefusedNamingIt)
{
	const uint16_t port = hw_serial::freeLoopbackPort();
	hw_serial::CameraServer first([] { return noisePair(8, 8, 1); }, port);
	EXPECT_EQ(first.port(), port);
	EXPECT_EQ(first.address(), "127.0.0.1:" + std::to_string(port));
	try
	{
		hw_serial::CameraServer second([] { return noisePair(8, 8, 1); }, port);
		ADD_FAILURE() << "two servers on one port";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find(first.address()), std::string::npos) << e.what();
	}
	hw_serial::CameraSocketClient client(first.address(), kTimeoutMs);
	EXPECT_TRUE(sameGreyPixels(client.grab().left, noisePair(8, 8, 1).left));
}

TEST(CameraSocket, AnEmptyImageFromTheGrabIsRefusedNamingIt)
{
	hw_serial::CameraServer server(
	    []
	    {
		    auto p = noisePair(8, 8, 1);
		    p.left = mrpt::img::CImage();
		    return p;
	    });
	hw_serial::CameraSocketClient client(server.address(), kTimeoutMs);
	const auto e = expectSerialError([&] { client.grab(); });
	EXPECT_EQ(e.kind(), Kind::Refused) << e.what();
	EXPECT_NE(std::string(e.what()).find("left image is empty"), std::string::npos) << e.what();
}

TEST(CameraSocket, MalformedAddressesAreRefusedNamingDeviceAndAddress)
{
	for (const std::string bad :
	     {"", "127.0.0.1", "127.0.0.1:", "127.0.0.1:0", "127.0.0.1:65536", "127.0.0.1:99999",
	      "127.0.0.1:+80", "127.0.0.1:080", "127.0.0.1: 80", "127.0.0.1:80 ", "127.0.0.1:8o",
	      "localhost:80", "10.0.0.1:80", "0.0.0.0:80", " 127.0.0.1:80", "127.0.0.1:80:81"})
	{
		try
		{
			hw_serial::CameraSocketClient c(bad, kTimeoutMs);
			ADD_FAILURE() << "accepted '" << bad << "'";
		}
		catch (const std::invalid_argument& e)
		{
			const std::string what = e.what();
			EXPECT_NE(what.find("device.camera"), std::string::npos) << what;
			EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << what;
			EXPECT_NE(what.find("127.0.0.1:PORT"), std::string::npos) << what;
		}
	}
	EXPECT_EQ(hw_serial::parseCameraAddress("127.0.0.1:1", "d"), 1);
	EXPECT_EQ(hw_serial::parseCameraAddress("127.0.0.1:65535", "d"), 65535);
}

TEST(CameraSocket, TheDeviceSectionIsNamedAsGiven)
{
	const std::string address = "127.0.0.1:" + std::to_string(hw_serial::freeLoopbackPort());
	const auto e = expectSerialError([&] { hw_serial::CameraSocketClient c(address, 100, "device.eye"); });
	EXPECT_EQ(e.device(), "device.eye");
}
