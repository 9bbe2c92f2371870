// The framing and message layer of the serial protocols, byte by byte (docs/serial.md).
#include <mrolr/hw_serial/Framing.h>
#include <mrolr/hw_serial/Message.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace mrolr::hw_serial;

namespace
{
std::vector<AssembledLine> drain(LineAssembler& a)
{
	std::vector<AssembledLine> out;
	AssembledLine l;
	while (a.next(l)) out.push_back(l);
	return out;
}
}  // namespace

TEST(Framing, ChecksumIsMrptsCrc32InUpperCaseHex)
{
	// the check value of this CRC-32 variant (reflected 0xEDB88320, init 0, no final XOR)
	EXPECT_EQ(lineChecksum("123456789"), 0x2DFD2D88u);
	EXPECT_EQ(frameLine("1 OK"), "1 OK*E63512F6\n");
	EXPECT_EQ(frameLine(""), "*00000000\n");
	EXPECT_EQ(frameLine("7 ODO?"), "7 ODO?*ADDD0B91\n");
}

TEST(Framing, UnframeAcceptsItsOwnFramesAndATrailingCarriageReturn)
{
	for (const std::string body : {"1 OK", "12 STEP 0.1 -0.2 0.5", "- ERR BADLINE why"})
	{
		std::string line = frameLine(body);
		line.pop_back();
		const auto u = unframeLine(line);
		ASSERT_TRUE(u.ok) << line << ": " << u.error;
		EXPECT_EQ(u.body, body);
		EXPECT_TRUE(unframeLine(line + "\r").ok);
	}
}

TEST(Framing, UnframeRejectsDamagedLines)
{
	EXPECT_FALSE(unframeLine("1 OK*E63512F7").ok);   // wrong checksum
	EXPECT_FALSE(unframeLine("1 OK*E63512F6 ").ok);  // trailing byte
	EXPECT_FALSE(unframeLine("1 OK*E63512F").ok);    // seven hex digits
	EXPECT_FALSE(unframeLine("1 OK*E63512Fg").ok);   // not hex
	EXPECT_FALSE(unframeLine("1 OK*E63512F6x").ok);
	EXPECT_FALSE(unframeLine("1 OK*e63512f6").ok);  // lower-case hex
	EXPECT_FALSE(unframeLine("1 OK").ok);           // no checksum
	EXPECT_FALSE(unframeLine("").ok);
	EXPECT_EQ(unframeLine("1 OK*E63512F7").error, "checksum mismatch");
	EXPECT_FALSE(unframeLine(std::string("1 O\0K*E63512F6", 14)).ok);  // NUL inside
	EXPECT_FALSE(unframeLine("1 \xffOK*E63512F6").ok);
	// a dropped byte anywhere in a real reply is caught
	std::string framed = frameLine("3 OK 0.25 -1.5 0.125 5000 4990 2.5");
	framed.pop_back();
	for (size_t i = 0; i < framed.size(); ++i)
	{
		std::string damaged = framed;
		damaged.erase(i, 1);
		EXPECT_FALSE(unframeLine(damaged).ok) << "byte " << i << " dropped: " << damaged;
	}
	// two equal bytes dropped: an XOR checksum cannot see it, the CRC must
	for (size_t i = 0; i < framed.size(); ++i)
		for (size_t j = i + 1; j < framed.size(); ++j)
			if (framed[i] == framed[j] && framed[i] != '*')
			{
				std::string damaged = framed;
				damaged.erase(j, 1);
				damaged.erase(i, 1);
				EXPECT_FALSE(unframeLine(damaged).ok)
				    << "bytes " << i << "," << j << ": " << damaged;
			}
}

TEST(Framing, AssemblerJoinsLinesSplitAtEveryByte)
{
	const std::string stream = frameLine("1 OK") + frameLine("2 OK 1 2 3") + frameLine("3 ERR X y");
	for (size_t chunk = 1; chunk <= stream.size(); ++chunk)
	{
		LineAssembler a;
		for (size_t i = 0; i < stream.size(); i += chunk) a.feed(stream.substr(i, chunk));
		const auto lines = drain(a);
		ASSERT_EQ(lines.size(), 3u) << "chunk " << chunk;
		EXPECT_EQ(lines[0].text, "1 OK*E63512F6");
		EXPECT_EQ(unframeLine(lines[1].text).body, "2 OK 1 2 3");
		EXPECT_EQ(unframeLine(lines[2].text).body, "3 ERR X y");
		EXPECT_EQ(a.pendingBytes(), 0u);
	}
}

TEST(Framing, AssemblerHoldsAnIncompleteLine)
{
	LineAssembler a;
	a.feed("1 O");
	EXPECT_TRUE(drain(a).empty());
	EXPECT_EQ(a.pendingBytes(), 3u);
	a.feed("K*E63512F6\n2");
	const auto lines = drain(a);
	ASSERT_EQ(lines.size(), 1u);
	EXPECT_EQ(lines[0].text, "1 OK*E63512F6");
	EXPECT_EQ(a.pendingBytes(), 1u);
	a.clear();
	EXPECT_EQ(a.pendingBytes(), 0u);
}

TEST(Framing, AssemblerReportsOverlongLinesOnceAndResynchronises)
{
	LineAssembler a(16);
	a.feed(std::string(1000, 'x'));
	a.feed(std::string(1000, 'y'));
	EXPECT_LE(a.pendingBytes(), 16u);  // bounded however much garbage arrives
	a.feed("\n" + frameLine("1 OK"));
	const auto lines = drain(a);
	ASSERT_EQ(lines.size(), 2u);
	EXPECT_TRUE(lines[0].overlong);
	EXPECT_EQ(lines[0].text, std::string(16, 'x'));
	EXPECT_FALSE(lines[1].overlong);
	EXPECT_EQ(lines[1].text, "1 OK*E63512F6");
}

TEST(Framing, AssemblerPassesGarbageAsLinesForTheCheckerToReject)
{
	LineAssembler a;
	a.feed(std::string("\x13\xff\x00 noise\n", 10));
	const auto lines = drain(a);
	ASSERT_EQ(lines.size(), 1u);
	EXPECT_FALSE(unframeLine(lines[0].text).ok);
	EXPECT_EQ(printableBytes(lines[0].text), "\\x13\\xFF\\x00 noise");
}

TEST(Message, ParsesRequestsAndReplies)
{
	auto p = parseMessage("12 STEP 0.1 -0.2 0.5");
	ASSERT_TRUE(p.ok) << p.error;
	EXPECT_EQ(p.message.seq, 12);
	EXPECT_EQ(p.message.word, "STEP");
	EXPECT_EQ(p.message.fields, (std::vector<std::string>{"0.1", "-0.2", "0.5"}));
	p = parseMessage("- ERR BADLINE checksum mismatch");
	ASSERT_TRUE(p.ok);
	EXPECT_EQ(p.message.seq, kNoSeq);
	EXPECT_EQ(p.message.fields.size(), 3u);
	p = parseMessage("9999 OK");
	ASSERT_TRUE(p.ok);
	EXPECT_TRUE(p.message.fields.empty());
}

TEST(Message, RejectsMalformedBodies)
{
	for (const char* bad : {"", "1", "OK", "0 OK", "10000 OK", "01 OK", "x OK", "1  OK", "1 OK ",
	                        " 1 OK", "1 OK 2  3", "-1 OK", "+1 OK"})
		EXPECT_FALSE(parseMessage(bad).ok) << "'" << bad << "'";
}

TEST(Message, FormatAndParseRoundTrip)
{
	const Message m{42, "MOVE", {"1", "-2.5", "3e-05"}};
	EXPECT_EQ(formatMessage(m), "42 MOVE 1 -2.5 3e-05");
	const auto p = parseMessage(formatMessage(m));
	ASSERT_TRUE(p.ok);
	EXPECT_EQ(p.message.fields, m.fields);
	EXPECT_EQ(formatMessage({kNoSeq, "ERR", {"BADLINE"}}), "- ERR BADLINE");
}

TEST(Message, NumbersRoundTripExactly)
{
	for (double v :
	     {0.0, -0.0, 0.1, -1.0 / 3.0, M_PI, 1e-300, 6.02e23, -915.0, 0.30000000000000004})
	{
		const auto text = formatNumber(v);
		EXPECT_EQ(parseNumbers({text}, 1, "v")[0], v) << text;
	}
	EXPECT_EQ(formatNumber(0.25), "0.25");
	EXPECT_EQ(formatNumber(-180), "-180");
}

TEST(Message, NonFiniteNumbersAreNeverSentNorAccepted)
{
	EXPECT_THROW(formatNumber(std::nan("")), std::invalid_argument);
	EXPECT_THROW(formatNumber(std::numeric_limits<double>::infinity()), std::invalid_argument);
	for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e999", "", "1.2.3", "0x10",
	                        "+1", "1,5", " 1", "1 ", "1e", "--1", "abc"})
		EXPECT_THROW(parseNumbers({bad}, 1, "STEP"), std::invalid_argument) << "'" << bad << "'";
}

TEST(Message, NumberErrorsNameTheCommandAndTheField)
{
	try
	{
		parseNumbers({"1", "x", "3"}, 3, "STEP");
		FAIL() << "no throw";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_STREQ(e.what(), "STEP: field 2 'x' is not a finite number");
	}
	try
	{
		parseNumbers({"1", "2"}, 3, "STEP");
		FAIL() << "no throw";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_STREQ(e.what(), "STEP: expected 3 numbers, got 2 fields");
	}
}

TEST(Message, IntegersAreStrict)
{
	EXPECT_EQ(parseInteger("-4990", "t"), -4990);
	EXPECT_EQ(parseInteger("0", "t"), 0);
	for (const char* bad : {"", "1.0", "1e3", "12a", " 1", "+1", "99999999999999999999999"})
		EXPECT_THROW(parseInteger(bad, "t"), std::invalid_argument) << "'" << bad << "'";
}
