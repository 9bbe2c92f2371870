// The camera socket's frames without sockets: exact header bytes, a pair through the payload and
// back, and payloads that must be refused (truncated, padded, another class, random bytes).
#include "CameraTestUtil.h"

#include <mrolr/hw_serial/CameraWire.h>
#include <mrolr/hw_serial/GreyImage.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

using namespace mrolr;
using camtest::noisePair;
using camtest::sameGreyPixels;

namespace
{
std::string payloadOf(const std::string& frame)
{
	return frame.substr(hw_serial::kCameraHeaderBytes);
}

/** Five doubles, the frame counter and @p obs, as an MRCI payload would hold them. */
std::string payloadWith(const mrpt::serialization::CSerializable& obs)
{
	mrpt::io::CMemoryStream mem;
	auto out = mrpt::serialization::archiveFrom(mem);
	for (int i = 0; i < 5; ++i) out << 1.0;
	out << uint64_t(7);
	out << obs;
	return std::string(static_cast<const char*>(mem.getRawBufferData()),
	                   size_t(mem.getTotalBytesCount()));
}
}  // namespace

TEST(CameraWire, HeaderIsMagicThenLittleEndianSeqAndLength)
{
	EXPECT_EQ(hw_serial::encodeCameraRequest(0x01020304u),
	          std::string("MRCQ\x04\x03\x02\x01\0\0\0\0", 12));
	EXPECT_EQ(hw_serial::encodeCameraError(7, "no"), std::string("MRCE\x07\0\0\0\x02\0\0\0no", 14));
	const auto images = hw_serial::encodeCameraImages(0xFFFFFFFFu, noisePair(4, 3, 1));
	EXPECT_EQ(images.substr(0, 8), std::string("MRCI\xFF\xFF\xFF\xFF"));
	EXPECT_EQ(hw_serial::decodeCameraHeader(images).length, images.size() - hw_serial::kCameraHeaderBytes);
}

TEST(CameraWire, HeadersRoundTripForEveryKind)
{
	for (auto kind : {hw_serial::CameraFrameKind::Images, hw_serial::CameraFrameKind::Error})
	{
		const hw_serial::CameraFrameHeader h{kind, 4000000000u, hw_serial::kCameraMaxPayloadBytes};
		const auto back = hw_serial::decodeCameraHeader(hw_serial::encodeCameraHeader(h));
		EXPECT_EQ(back.kind, kind);
		EXPECT_EQ(back.seq, h.seq);
		EXPECT_EQ(back.length, h.length);
	}
	EXPECT_EQ(hw_serial::decodeCameraHeader(hw_serial::encodeCameraRequest(9)).kind,
	          hw_serial::CameraFrameKind::Request);
}

TEST(CameraWire, UnknownMagicOverlongLengthOrARequestWithPayloadAreRefused)
{
	EXPECT_THROW(hw_serial::decodeCameraHeader(std::string("MRCX\0\0\0\0\0\0\0\0", 12)),
	             hw_serial::CameraWireError);
	EXPECT_THROW(hw_serial::decodeCameraHeader(std::string("mrcq\0\0\0\0\0\0\0\0", 12)),
	             hw_serial::CameraWireError);
	EXPECT_THROW(hw_serial::decodeCameraHeader(hw_serial::encodeCameraHeader(
	                 {hw_serial::CameraFrameKind::Images, 1, hw_serial::kCameraMaxPayloadBytes + 1})),
	             hw_serial::CameraWireError);
	EXPECT_THROW(hw_serial::decodeCameraHeader(std::string("MRCQ\0\0\0\0\x01\0\0\0", 12)),
	             hw_serial::CameraWireError);
	EXPECT_THROW(hw_serial::decodeCameraHeader("MRCQ"), std::invalid_argument);
}

TEST(CameraWire, APairRoundTripsExactlyThroughThePayload)
{
	auto sent = noisePair(33, 17, 4);  // odd sizes: no row padding to hide behind
	sent.frame = 123456789012ull;
	const auto got = hw_serial::decodeCameraImages(payloadOf(hw_serial::encodeCameraImages(5, sent)));
	EXPECT_EQ(got.frame, sent.frame);
	EXPECT_TRUE(sameGreyPixels(got.left, sent.left));
	EXPECT_TRUE(sameGreyPixels(got.right, sent.right));
	EXPECT_EQ(got.time_s, sent.time_s);
	EXPECT_EQ(got.angles.pan, sent.angles.pan);
	EXPECT_EQ(got.angles.verg_right, sent.angles.verg_right);
}

TEST(CameraWire, TheObservationHoldsBothImagesAndTheTimestamp)
{
	const auto sent = noisePair(20, 10, 2);
	const std::string payload = payloadOf(hw_serial::encodeCameraImages(1, sent));
	mrpt::io::CMemoryStream mem;
	mem.assignMemoryNotOwn(payload.data(), payload.size());
	auto in = mrpt::serialization::archiveFrom(mem);
	double d[5];
	for (double& x : d) in >> x;
	uint64_t frame = 0;
	in >> frame;
	EXPECT_EQ(frame, sent.frame);
	const auto obs = in.ReadObject<mrpt::obs::CObservationStereoImages>();
	ASSERT_TRUE(obs);
	EXPECT_TRUE(obs->hasImageRight);
	EXPECT_FALSE(obs->hasImageDisparity);
	EXPECT_TRUE(sameGreyPixels(obs->imageLeft, sent.left));
	EXPECT_TRUE(sameGreyPixels(obs->imageRight, sent.right));
	EXPECT_NEAR(mrpt::Clock::toDouble(obs->timestamp), sent.time_s, 1e-6);  // 100 ns ticks
	EXPECT_EQ(obs->sensorLabel, hw_serial::kCameraSensorLabel);
	EXPECT_EQ(d[0], sent.time_s);
	EXPECT_EQ(d[2], sent.angles.tilt);
}

TEST(CameraWire, ColourIsSentAsItsGreyConversion)
{
	auto pair = noisePair(16, 8, 3);
	mrpt::img::CImage colour(16, 8, mrpt::img::CH_RGB);
	for (unsigned y = 0; y < 8; ++y)
		for (unsigned x = 0; x < 48; ++x) colour.ptrLine<uint8_t>(y)[x] = uint8_t(x * 5 + y);
	pair.left = colour;
	const auto got = hw_serial::decodeCameraImages(payloadOf(hw_serial::encodeCameraImages(1, pair)));
	EXPECT_FALSE(got.left.isColor());
	EXPECT_TRUE(sameGreyPixels(got.left, colour.grayscale()));
}

TEST(CameraWire, EmptyImagesAreNotEncoded)
{
	auto pair = noisePair(8, 8, 1);
	pair.right = mrpt::img::CImage();
	EXPECT_THROW(hw_serial::encodeCameraImages(1, pair), std::invalid_argument);
}

TEST(CameraWire, EveryTruncationOrPaddingOfAPayloadIsRefused)
{
	const std::string payload = payloadOf(hw_serial::encodeCameraImages(1, noisePair(6, 4, 1)));
	for (size_t n = 0; n < payload.size(); ++n)
		EXPECT_THROW(hw_serial::decodeCameraImages(payload.substr(0, n)), hw_serial::CameraWireError) << n;
	EXPECT_THROW(hw_serial::decodeCameraImages(payload + '\0'), hw_serial::CameraWireError);
}

TEST(CameraWire, AnotherObservationClassIsRefused)
{
	mrpt::obs::CObservationImage mono;
	mono.image = camtest::noiseImage(4, 4, 1);
	EXPECT_THROW(hw_serial::decodeCameraImages(payloadWith(mono)), hw_serial::CameraWireError);
}

TEST(CameraWire, AStereoObservationWithoutItsRightImageIsRefused)
{
	mrpt::obs::CObservationStereoImages obs;
	obs.imageLeft = camtest::noiseImage(4, 4, 1);
	obs.hasImageRight = false;
	EXPECT_THROW(hw_serial::decodeCameraImages(payloadWith(obs)), hw_serial::CameraWireError);
}

TEST(CameraWire, RandomPayloadsAreRefusedNeverCrash)
{
	std::mt19937 rng(11);
	for (int i = 0; i < 300; ++i)
	{
		std::string junk(rng() % 600, '\0');
		for (char& c : junk) c = char(rng());
		EXPECT_THROW(hw_serial::decodeCameraImages(junk), hw_serial::CameraWireError);
	}
}
