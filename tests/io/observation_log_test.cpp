// The streamed rawlog: records read back in order, a comment keeps its label, a torn end is named,
// and the writer thread keeps the order, reports a failed write and writes what is queued.
#include <mrolr/io/ObservationLog.h>
#include <mrolr/io/ObservationQueue.h>
#include <mrolr/io/Rawlog.h>

#include <mrpt/obs/CObservationRawDAQ.h>

#include "../common/FreshTempDir.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
mrpt::obs::CObservationRawDAQ::Ptr numbered(double i)
{
	auto o = mrpt::obs::CObservationRawDAQ::Create();
	o->sensorLabel = "N";
	o->timestamp = io::stampOf(i);
	o->AIN_double = {i};
	return o;
}

std::vector<double> numbersIn(const std::string& path)
{
	std::vector<double> out;
	for (const auto& o : io::readObservationLog(path).observations)
		if (const auto d = std::dynamic_pointer_cast<mrpt::obs::CObservationRawDAQ>(o))
			out.push_back(d->AIN_double.at(0));
	return out;
}
}  // namespace

TEST(ObservationLog, ReadsBackEveryRecordInOrderAndCommentsKeepTheirLabels)
{
	const auto dir = mrolr::test_support::freshTempDir("observation_log_order");
	{
		io::ObservationLogWriter w(dir + "/a.rawlog");
		for (int i = 0; i < 5; ++i) w.write(*numbered(i));
		w.write(*io::labelledComment("NOTE", "two\nlines", io::stampOf(0)));
		EXPECT_EQ(w.count(), 6u);
		EXPECT_FALSE(fs::exists(w.imagesDir())) << "no images, no folder";
	}
	const auto log = io::readObservationLog(dir + "/a.rawlog");
	ASSERT_EQ(log.observations.size(), 6u);
	EXPECT_TRUE(log.torn.empty());
	EXPECT_EQ(numbersIn(dir + "/a.rawlog"), (std::vector<double>{0, 1, 2, 3, 4}));
	const auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(log.observations[5]);
	ASSERT_TRUE(c);
	EXPECT_EQ(c->sensorLabel, "NOTE");
	EXPECT_EQ(c->text, "two\nlines");
}

TEST(ObservationLog, ATornLastRecordIsNamedAndTheOnesBeforeItRead)
{
	const auto dir = mrolr::test_support::freshTempDir("observation_log_torn");
	{
		io::ObservationLogWriter w(dir + "/a.rawlog");
		for (int i = 0; i < 4; ++i) w.write(*numbered(i));
	}
	fs::resize_file(dir + "/a.rawlog", fs::file_size(dir + "/a.rawlog") - 3);
	const auto log = io::readObservationLog(dir + "/a.rawlog");
	EXPECT_EQ(log.observations.size(), 3u);
	EXPECT_NE(log.torn.find("record 3"), std::string::npos) << log.torn;
}

TEST(ObservationQueue, WritesInTheOrderPostedAndEverythingQueuedBeforeItCloses)
{
	const auto dir = mrolr::test_support::freshTempDir("observation_queue_order");
	{
		io::ObservationQueue q(dir + "/a.rawlog", 4);  // a small queue: post() has to wait
		for (int i = 0; i < 200; ++i)
			q.post([i](io::ObservationLogWriter& w) { w.write(*numbered(i)); });
	}
	const auto n = numbersIn(dir + "/a.rawlog");
	ASSERT_EQ(n.size(), 200u);
	for (int i = 0; i < 200; ++i) EXPECT_EQ(n[i], i);
}

TEST(ObservationQueue, AFailedWriteIsThrownByTheNextPostNamingTheFile)
{
	const auto dir = mrolr::test_support::freshTempDir("observation_queue_failure");
	io::ObservationQueue q(dir + "/a.rawlog");
	q.post([](io::ObservationLogWriter& w) { w.write(*numbered(1)); });
	q.post([](io::ObservationLogWriter&) { throw std::runtime_error("disk full"); });
	try
	{
		q.flush();
		ADD_FAILURE() << "the failure was not reported";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("a.rawlog"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos) << e.what();
	}
	EXPECT_THROW(q.post([](io::ObservationLogWriter& w) { w.write(*numbered(2)); }),
	             std::runtime_error);
	EXPECT_EQ(numbersIn(dir + "/a.rawlog"), std::vector<double>{1});
}
