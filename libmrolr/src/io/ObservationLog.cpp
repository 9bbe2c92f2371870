// The streamed observations-only rawlog: one flushed record per observation.
#include <mrolr/io/ObservationLog.h>
#include <mrolr/io/Rawlog.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace mrolr::io
{
namespace fs = std::filesystem;

ObservationLogWriter::ObservationLogWriter(const std::string& path)
    : path_(path), images_dir_(imagesDirFor(path))
{
	std::error_code ec;
	if (fs::path(path).has_parent_path()) fs::create_directories(fs::path(path).parent_path(), ec);
	if (ec) throw std::runtime_error("cannot create the folder of rawlog " + path + ": " + ec.message());
	file_.open(path, std::ios::binary | std::ios::trunc);
	if (!file_) throw std::runtime_error("cannot open rawlog " + path + " for writing");
}

void ObservationLogWriter::write(const mrpt::obs::CObservation& obs)
{
	mrpt::io::CMemoryStream buffer;
	auto out = mrpt::serialization::archiveFrom(buffer);
	out.WriteObject(&obs);
	file_.write(static_cast<const char*>(buffer.getRawBufferData()),
	            static_cast<std::streamsize>(buffer.getTotalBytesCount()));
	file_.flush();  // in the kernel now: a killed process keeps this record
	if (!file_) throw std::runtime_error("cannot write to rawlog " + path_);
	++count_;
	bytes_ += buffer.getTotalBytesCount();
}

mrpt::img::CImage ObservationLogWriter::external(const mrpt::img::CImage& img,
                                                 const std::string& name) const
{
	const auto file = (fs::path(images_dir_) / name).string();
	std::error_code ec;
	fs::create_directories(images_dir_, ec);  // on the first image
	if (ec || !img.saveToFile(file)) throw std::runtime_error("cannot write image " + file);
	image_bytes_ += fs::file_size(file, ec);
	++images_;
	mrpt::img::CImage e;
	e.setExternalStorage(name);
	return e;
}

mrpt::obs::CObservationComment::Ptr labelledComment(const std::string& label,
                                                    const std::string& text,
                                                    mrpt::Clock::time_point stamp)
{
	auto c = mrpt::obs::CObservationComment::Create();
	c->sensorLabel = label;
	c->timestamp = stamp;
	c->text = label + "\n" + text;
	return c;
}

namespace
{
/** The first line of an MRPT exception's text (without its call stack). */
std::string mrptMessageOf(const std::string& what)
{
	return what.substr(0, what.find('\n'));
}

/** A labelledComment's label and text back apart. */
void restoreLabel(mrpt::obs::CObservationComment& c)
{
	const auto nl = c.text.find('\n');
	if (!c.sensorLabel.empty() || nl == std::string::npos || nl == 0) return;
	for (size_t i = 0; i < nl; ++i)
		if (!(std::isupper(static_cast<unsigned char>(c.text[i])) ||
		      std::isdigit(static_cast<unsigned char>(c.text[i])) || c.text[i] == '_'))
			return;
	c.sensorLabel = c.text.substr(0, nl);
	c.text = c.text.substr(nl + 1);
}
}  // namespace

ObservationLog readObservationLog(const std::string& path)
{
	mrpt::io::CFileGZInputStream file;
	if (!fs::exists(path) || !file.open(path)) throw std::runtime_error("cannot read rawlog " + path);
	auto in = mrpt::serialization::archiveFrom(file);
	ObservationLog log;
	const auto size = fs::file_size(path);
	for (;;)
	{
		const auto at = file.getPosition();
		if (at >= size) break;
		mrpt::serialization::CSerializable::Ptr obj;
		try
		{
			obj = in.ReadObject();
		}
		catch (const std::exception& e)
		{
			if (log.observations.empty())
				throw std::runtime_error(path + ": not a rawlog (its first record is unreadable: " +
				                         mrptMessageOf(e.what()) + ")");
			log.torn = "record " + std::to_string(log.observations.size()) + " at byte " +
			           std::to_string(at) + " of " + std::to_string(size) +
			           " is incomplete or unreadable";
			break;
		}
		auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
		if (!obs)
			throw std::runtime_error(path + ": record " + std::to_string(log.observations.size()) +
			                         " is a " + obj->GetRuntimeClass()->className +
			                         ", not an observation (not an observations-only rawlog)");
		if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obs)) restoreLabel(*c);
		log.observations.push_back(std::move(obs));
	}
	return log;
}

std::string externalFile(const mrpt::img::CImage& external, const std::string& rawlog_path)
{
	return (fs::path(imagesDirFor(rawlog_path)) / external.getExternalStorageFile()).string();
}

mrpt::img::CImage loadExternal(const mrpt::img::CImage& external, const std::string& rawlog_path)
{
	const auto file = externalFile(external, rawlog_path);
	mrpt::img::CImage img;
	if (!fs::exists(file) || !img.loadFromFile(file))
		throw std::runtime_error(rawlog_path + ": cannot read its external image " + file);
	return img;
}

}  // namespace mrolr::io
