#pragma once
/** A rawlog written as it happens: MRPT's observations-only rawlog format (a plain sequence of
 * serialized CObservation objects, which rawlog-edit and RawLogViewer read), its images external
 * in `<stem>_Images/`. Each observation reaches the operating system before write() returns, so a
 * process killed at any moment leaves a file whose every complete record reads back; the reader
 * stops at a torn last record and says so. */
#include <mrpt/img/CImage.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationComment.h>

#include <fstream>
#include <string>
#include <vector>

namespace mrolr::io
{
/** Appends observations to a new rawlog. */
class ObservationLogWriter
{
 public:
	/** Creates @p path (and its folder; the images folder with the first image); throws std::runtime_error naming the
	 * path when it cannot. */
	explicit ObservationLogWriter(const std::string& path);
	/** Serializes @p obs, appends it and flushes it to the operating system; throws
	 * std::runtime_error naming the file when the write fails. */
	void write(const mrpt::obs::CObservation& obs);
	/** Saves @p img as `<images dir>/<name>` (the format from the extension) and returns an image
	 * that refers to it, for an observation to carry. */
	mrpt::img::CImage external(const mrpt::img::CImage& img, const std::string& name) const;
	size_t count() const { return count_; }
	/** Bytes written to the rawlog, and to its images folder (and how many images). */
	uint64_t bytes() const { return bytes_; }
	uint64_t imageBytes() const { return image_bytes_; }
	size_t images() const { return images_; }
	const std::string& path() const { return path_; }
	const std::string& imagesDir() const { return images_dir_; }

 private:
	std::string path_, images_dir_;
	std::ofstream file_;
	size_t count_ = 0;
	uint64_t bytes_ = 0;
	mutable uint64_t image_bytes_ = 0;
	mutable size_t images_ = 0;
};

/** A comment observation whose label survives the file: MRPT 2.5 does not serialize a
 * CObservationComment's sensorLabel, so its text begins with the label on a line of its own
 * (readObservationLog restores it). @p label is upper case, digits and '_'. */
mrpt::obs::CObservationComment::Ptr labelledComment(const std::string& label,
                                                    const std::string& text,
                                                    mrpt::Clock::time_point stamp);

/** What readObservationLog found. */
struct ObservationLog
{
	std::vector<mrpt::obs::CObservation::Ptr> observations;  ///< every complete record, in order
	/** Empty when the file ended cleanly; otherwise why the record after the last one could not
	 * be read (a torn record from a killed writer, or garbage), with its byte offset. */
	std::string torn;
};

/** Reads every complete observation of @p path (external images left unloaded: see
 * loadExternal); a labelledComment gets its label back and its text without it. Throws std::runtime_error naming the file when it cannot be opened or holds
 * something other than observations. */
ObservationLog readObservationLog(const std::string& path);

/** The pixels of an image stored externally beside rawlog @p rawlog_path (throws naming the file
 * when it is missing or unreadable). */
mrpt::img::CImage loadExternal(const mrpt::img::CImage& external, const std::string& rawlog_path);
/** The file loadExternal reads for @p external. */
std::string externalFile(const mrpt::img::CImage& external, const std::string& rawlog_path);

}  // namespace mrolr::io
