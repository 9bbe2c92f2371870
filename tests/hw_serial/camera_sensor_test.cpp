// CameraSensorStereo on CCameraSensor's offline image_dir grabber (PNG files the test writes), and
// the errors when a camera is missing or its section is wrong.
#include "CameraTestUtil.h"
#include "ExpectSerialError.h"
#include "../common/ThrownMessage.h"

#include <mrolr/hw_serial/CameraSensorStereo.h>
#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace mrolr;
using Kind = hw_serial::SerialDeviceError::Kind;
namespace fs = std::filesystem;

namespace
{
constexpr int kFrames = 3;

/** A folder of left_000.png.. and right_000.png.. noise images, removed at the end. */
struct ImageFolder
{
	fs::path dir;
	std::vector<mrpt::img::CImage> left, right;

	ImageFolder()
	    : dir(fs::temp_directory_path() /
	          ("mrolr_camera_" + std::to_string(::getpid()) + "_" + std::to_string(counter()++)))
	{
		fs::create_directories(dir);
		for (int i = 0; i < kFrames; ++i)
		{
			left.push_back(camtest::noiseImage(40, 30, 10 + i));
			right.push_back(camtest::noiseImage(40, 30, 20 + i));
			left.back().saveToFile(file("left", i));
			right.back().saveToFile(file("right", i));
		}
	}
	~ImageFolder() { fs::remove_all(dir); }
	std::string file(const std::string& side, int i) const
	{
		char name[32];
		std::snprintf(name, sizeof(name), "%s_%03d.png", side.c_str(), i);
		return (dir / name).string();
	}
	static int& counter()
	{
		static int n = 0;
		return n;
	}
};

std::string imageDirSection(const std::string& name, const std::string& dir,
                            const std::string& side)
{
	return "[" + name + "]\ngrabber_type = image_dir\nimage_dir_url = " + dir +
	       "\nleft_format = " + side +
	       "_%03d.png\nstart_index = 0\nend_index = " + std::to_string(kFrames - 1) + "\n";
}

mrpt::config::CConfigFileMemory stereoConfig(const std::string& dir)
{
	return mrpt::config::CConfigFileMemory(imageDirSection("device.camera.left", dir, "left") +
	                                       imageDirSection("device.camera.right", dir, "right"));
}

/** The ConfigError's message, or a failure when none was thrown. */
std::string configError(const mrpt::config::CConfigFileBase& cfg)
{
	const std::string what = test_support::messageOf<util::ConfigError>(
	    [&] { hw_serial::CameraSensorStereo cameras(cfg); });
	if (what.empty()) ADD_FAILURE() << "no ConfigError";
	return what;
}

bool has(const std::string& text, const std::string& part)
{
	return text.find(part) != std::string::npos;
}
}  // namespace

TEST(CameraSensorStereo, GrabsTheFoldersImagesInOrderAsGrey)
{
	ImageFolder folder;
	const auto cfg = stereoConfig(folder.dir.string());
	hw_serial::CameraSensorStereo cameras(cfg);
	for (int i = 0; i < kFrames; ++i)
	{
		const double before_s = mrpt::Clock::toDouble(mrpt::Clock::now());
		const auto pair = cameras.grab();
		const double after_s = mrpt::Clock::toDouble(mrpt::Clock::now());
		EXPECT_TRUE(camtest::sameGreyPixels(pair.left, folder.left[size_t(i)])) << i;
		EXPECT_TRUE(camtest::sameGreyPixels(pair.right, folder.right[size_t(i)])) << i;
		EXPECT_GE(pair.time_s, before_s - 1e-3);  // the frame's own timestamp
		EXPECT_LE(pair.time_s, after_s + 1e-3);
		EXPECT_EQ(pair.angles.pan, 0.0);  // left to SerialHead
	}
}

TEST(CameraSensorStereo, ColourFilesArriveAsTheirGreyConversion)
{
	ImageFolder folder;
	mrpt::img::CImage colour(40, 30, mrpt::img::CH_RGB);
	for (unsigned y = 0; y < 30; ++y)
		for (unsigned x = 0; x < 120; ++x) colour.ptrLine<uint8_t>(y)[x] = uint8_t(3 * x + 7 * y);
	colour.saveToFile(folder.file("left", 0));
	mrpt::img::CImage reloaded;
	ASSERT_TRUE(reloaded.loadFromFile(folder.file("left", 0)));
	hw_serial::CameraSensorStereo cameras(stereoConfig(folder.dir.string()));
	const auto pair = cameras.grab();
	EXPECT_FALSE(pair.left.isColor());
	EXPECT_TRUE(camtest::sameGreyPixels(pair.left, reloaded.grayscale()));
}

TEST(CameraSensorStereo, PastTheLastImageIsADisconnectNamingTheSection)
{
	ImageFolder folder;
	hw_serial::CameraSensorStereo cameras(stereoConfig(folder.dir.string()));
	for (int i = 0; i < kFrames; ++i) cameras.grab();
	const auto e = expectSerialError([&] { cameras.grab(); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	EXPECT_EQ(e.device(), "device.camera.left");
	EXPECT_EQ(e.port(), "image_dir " + folder.dir.string());
}

TEST(CameraSensorStereo, AMissingFolderFailsInTheConstructorNamingSectionAndFolder)
{
	ImageFolder folder;
	const std::string missing = (folder.dir / "nowhere").string();
	const mrpt::config::CConfigFileMemory cfg(
	    imageDirSection("device.camera.left", folder.dir.string(), "left") +
	    imageDirSection("device.camera.right", missing, "right"));
	const auto e = expectSerialError([&] { hw_serial::CameraSensorStereo cameras(cfg); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	EXPECT_EQ(e.device(), "device.camera.right");
	EXPECT_TRUE(has(e.what(), missing)) << e.what();
}

TEST(CameraSensorStereo, AFolderWithoutTheFirstImageFailsInTheConstructor)
{
	ImageFolder folder;
	fs::remove(folder.file("left", 0));
	const auto e =
	    expectSerialError([&] { hw_serial::CameraSensorStereo c(stereoConfig(folder.dir.string())); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	EXPECT_TRUE(has(e.what(), "left_000.png")) << e.what();
}

TEST(CameraSensorStereo, ACameraIndexThatDoesNotExistFailsInTheConstructor)
{
	const mrpt::config::CConfigFileMemory cfg(
	    "[device.camera.left]\ngrabber_type = opencv\ncv_camera_index = 97\n"
	    "[device.camera.right]\ngrabber_type = opencv\ncv_camera_index = 98\n");
	const auto e = expectSerialError([&] { hw_serial::CameraSensorStereo cameras(cfg); });
	EXPECT_EQ(e.kind(), Kind::Disconnected) << e.what();
	EXPECT_EQ(e.device(), "device.camera.left");
	EXPECT_EQ(e.port(), "opencv camera 97");
	EXPECT_TRUE(has(e.what(), "cannot open the camera")) << e.what();
}

TEST(CameraSensorStereo, SectionMistakesAreConfigErrorsNamingSectionAndKey)
{
	ImageFolder folder;
	const std::string dir = folder.dir.string();
	const std::string left = imageDirSection("device.camera.left", dir, "left");
	const std::string right = imageDirSection("device.camera.right", dir, "right");
	const auto missing = configError(mrpt::config::CConfigFileMemory(left));
	EXPECT_TRUE(has(missing, "[device.camera.right]") && has(missing, "grabber_type")) << missing;
	const auto unknown = configError(
	    mrpt::config::CConfigFileMemory(left + "[device.camera.right]\ngrabber_type = webcam\n"));
	EXPECT_TRUE(has(unknown, "'webcam'") && has(unknown, "grabber_type")) << unknown;
	const auto format = configError(mrpt::config::CConfigFileMemory(
	    imageDirSection("device.camera.left", dir, "left_%s") + right));
	EXPECT_TRUE(has(format, "left_format") && has(format, "%s")) << format;
	const auto stereo = configError(
	    mrpt::config::CConfigFileMemory(left + right + "right_format = right_%03d.png\n"));
	EXPECT_TRUE(has(stereo, "[device.camera.right]") && has(stereo, "right_format")) << stereo;
	const auto percent = configError(mrpt::config::CConfigFileMemory(
	    left + imageDirSection("device.camera.right", dir + "/100%d", "right")));
	EXPECT_TRUE(has(percent, "image_dir_url")) << percent;
}

TEST(CameraSensorStereo, ItsPairsTravelTheCameraSocketUnchanged)
{
	ImageFolder folder;
	hw_serial::CameraSensorStereo cameras(stereoConfig(folder.dir.string()));
	hw_serial::CameraServer server([&] { return cameras.grab(); });
	hw_serial::CameraSocketClient client(server.address(), 2000);
	const auto pair = client.grab();
	EXPECT_TRUE(camtest::sameGreyPixels(pair.left, folder.left[0]));
	EXPECT_TRUE(camtest::sameGreyPixels(pair.right, folder.right[0]));
}
