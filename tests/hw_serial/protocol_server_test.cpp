// The device side of the protocols: requests in, exact reply bytes out (docs/serial.md).
#include "FakeDevices.h"

#include <mrolr/hw_serial/ProtocolServer.h>

#include <gtest/gtest.h>

using namespace mrolr::hw;
using namespace mrolr::hw_serial;

namespace
{
/** Frames @p body as the host would, passes it to the server, returns the reply body. */
std::string ask(ProtocolServer& server, const std::string& body)
{
	std::string line = frameLine(body);
	line.pop_back();
	std::string reply = server.handleLine({line, false});
	EXPECT_EQ(reply.back(), '\n');
	reply.pop_back();
	const auto u = unframeLine(reply);
	EXPECT_TRUE(u.ok) << reply;
	return u.body;
}

/** A recording base behind its protocol server. */
class BaseProtocol : public ::testing::Test
{
 protected:
	fake::Base base;
	BaseHandler handler{base};
	ProtocolServer server{handler};
};
}  // namespace

TEST_F(BaseProtocol, BaseStepsAndReportsOdometry)
{
	EXPECT_EQ(ask(server, "1 ID?"), "1 OK LABMATE 1");
	EXPECT_EQ(ask(server, "2 STEP 0.2 0.1 0.5"), "2 OK");
	ASSERT_EQ(base.steps.size(), 1u);
	EXPECT_EQ(base.steps[0].v1_mps, 0.2);
	EXPECT_EQ(base.steps[0].v2_mps, 0.1);
	EXPECT_EQ(base.steps[0].dt_s, 0.5);
	EXPECT_EQ(ask(server, "3 ODO?"), "3 OK 0.1 0 0 10 -3 0.5 0");
}

TEST_F(BaseProtocol, ExactReplyBytes)
{
	EXPECT_EQ(server.handleLine({"5 STEP 0 0 0.5*" + std::string("3B3D37F1"), false}),
	          frameLine("5 OK"));
	EXPECT_EQ(frameLine("5 OK"), "5 OK*695785A1\n");
}

TEST_F(BaseProtocol, ARepeatedRequestIsAnsweredFromTheCacheNotExecutedTwice)
{
	EXPECT_EQ(ask(server, "7 STEP 0.2 0.2 1"), "7 OK");
	EXPECT_EQ(ask(server, "7 STEP 0.2 0.2 1"), "7 OK");
	EXPECT_EQ(base.steps.size(), 1u);
	EXPECT_EQ(server.executed(), 1u);
	EXPECT_EQ(ask(server, "8 STEP 0.2 0.2 1"), "8 OK");
	EXPECT_EQ(base.steps.size(), 2u);
}

TEST_F(BaseProtocol, WrongFieldCountsAndBadNumbersAreBadArg)
{
	EXPECT_EQ(ask(server, "1 STEP 0.2 0.1"), "1 ERR BADARG STEP: expected 3 numbers, got 2 fields");
	EXPECT_EQ(ask(server, "2 STEP 0.2 0.1 0.5 9").rfind("2 ERR BADARG", 0), 0u);
	EXPECT_EQ(ask(server, "3 STEP nan 0.1 0.5"),
	          "3 ERR BADARG STEP: field 1 'nan' is not a finite number");
	EXPECT_EQ(ask(server, "4 STEP 0.1 inf 0.5").rfind("4 ERR BADARG", 0), 0u);
	EXPECT_EQ(ask(server, "5 STEP 0.1 0.1 -1").rfind("5 ERR BADARG", 0), 0u);
	EXPECT_EQ(ask(server, "6 ODO? 1"), "6 ERR BADARG ODO? takes no arguments, got 1");
	EXPECT_TRUE(base.steps.empty());
}

TEST(ProtocolServer, UnknownCommandsAreBadCmd)
{
	fake::Base base;
	BaseHandler bh(base);
	ProtocolServer bs(bh);
	EXPECT_EQ(ask(bs, "1 FLY 1 2"), "1 ERR BADCMD unknown command 'FLY' for LABMATE");
	EXPECT_EQ(ask(bs, "2 step 0 0 1"), "2 ERR BADCMD unknown command 'step' for LABMATE");
	fake::Arm arm;
	ArmHandler ah(arm);
	ProtocolServer as(ah);
	EXPECT_EQ(ask(as, "1 ANG?"), "1 ERR BADCMD unknown command 'ANG?' for RTX");
	EXPECT_EQ(ask(as, "2 STEP 1 2 3"), "2 ERR BADCMD unknown command 'STEP' for RTX");
}

TEST_F(BaseProtocol, DamagedLinesGetBadLineWithoutSequenceNumber)
{
	const auto reply = [&](const std::string& line, bool overlong = false)
	{
		std::string r = server.handleLine({line, overlong});
		r.pop_back();
		return unframeLine(r).body;
	};
	EXPECT_EQ(reply("1 STEP 0 0 0.5*00000000"), "- ERR BADLINE checksum mismatch");
	EXPECT_EQ(reply("garbage"), "- ERR BADLINE no checksum at the end of the line");
	EXPECT_EQ(reply(std::string("\x01\x02", 2)), "- ERR BADLINE non-printable byte in line");
	EXPECT_EQ(reply("xxxx", true), "- ERR BADLINE line too long");
	std::string no_seq = frameLine("STEP");
	no_seq.pop_back();
	EXPECT_EQ(reply(no_seq).rfind("- ERR BADLINE expected", 0), 0u);
	EXPECT_TRUE(base.steps.empty());
}

TEST(ProtocolServer, HeadMovesAndRefusesLimitsWithLimit)
{
	fake::Head head;
	HeadHandler handler(head);
	ProtocolServer server(handler);
	EXPECT_EQ(ask(server, "1 MOVE 0.1 -0.2 0.05 -0.05"), "1 OK 0.5");
	EXPECT_EQ(ask(server, "2 ANG?"), "2 OK 0.1 -0.2 0.05 -0.05");
	EXPECT_EQ(ask(server, "3 MOVE 4 0 0 0"), "3 ERR LIMIT pan beyond its limit");
	EXPECT_EQ(head.moves, 1);
	EXPECT_EQ(ask(server, "4 MOVE 0 0 0").rfind("4 ERR BADARG", 0), 0u);
}

TEST(ProtocolServer, ArmMovesGripsAndRefusesLimits)
{
	fake::Arm arm;
	ArmHandler handler(arm);
	ProtocolServer server(handler);
	EXPECT_EQ(ask(server, "1 MOVE 500 10 -20 30 -40 50 -60"), "1 OK");
	EXPECT_EQ(ask(server, "2 JNT?"), "2 OK 500 10 -20 30 -40 50 -60");
	EXPECT_EQ(ask(server, "3 GRIP 1"), "3 OK");
	EXPECT_EQ(ask(server, "4 GRIP?"), "4 OK 1 0");
	EXPECT_EQ(ask(server, "5 GRIP 2").rfind("5 ERR BADARG", 0), 0u);
	EXPECT_EQ(ask(server, "6 GRIP").rfind("6 ERR BADARG", 0), 0u);
	EXPECT_EQ(ask(server, "7 MOVE -1 0 0 0 0 0 0"),
	          "7 ERR LIMIT arm joint d1_mm = -1 outside [0, 915]");
	EXPECT_EQ(ask(server, "8 MOVE 911 0 0 0 0 0 0"), "8 ERR BLOCKED the gripper met table 'main'");
	EXPECT_EQ(arm.j[0], 500);
	EXPECT_TRUE(arm.closed);
}

TEST(ProtocolServer, ArmDocksAndARefusedUndockIsAFault)
{
	fake::Arm arm;
	ArmHandler handler(arm);
	ProtocolServer server(handler);
	EXPECT_EQ(ask(server, "1 DOCK?"), "1 OK 0");
	EXPECT_EQ(ask(server, "2 DOCK 1"), "2 OK");
	EXPECT_EQ(ask(server, "3 DOCK?"), "3 OK 1");
	EXPECT_EQ(ask(server, "4 DOCK yes").rfind("4 ERR BADARG DOCK takes one field", 0), 0u);
	EXPECT_EQ(ask(server, "5 GRIP 1"), "5 OK");
	EXPECT_EQ(ask(server, "6 DOCK 0"), "6 ERR FAULT the arm holds something");
	EXPECT_TRUE(arm.is_docked);
}
