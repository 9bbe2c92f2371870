#pragma once
/** Reading and writing wire-frame models in the `.wf` text format (docs/model.md):
 *
 *     # mrolr wire-frame 1
 *     units mm
 *     frame object            # or left_camera, c0
 *     line ID x1 y1 z1 x2 y2 z2
 *     conic ID cx cy cz nx ny nz ax ay az a b t1 t2
 *     grasp x y z yaw_deg pitch_deg roll_deg
 *     clique FOCUS N ID1 ... IDN
 *
 * `#` starts a comment; blank lines are ignored. IDs are positive and unique among lines and
 * conics. Numbers are written with 17 significant digits so that write→read is exact. */

#include <mrolr/model/WireFrame.h>

#include <iosfwd>
#include <stdexcept>
#include <string>

namespace mrolr::model
{
/** A malformed `.wf` file; what() reads "SOURCE:LINE: reason". */
class WireFrameFormatError : public std::runtime_error
{
 public:
	WireFrameFormatError(const std::string& source, int line_no, const std::string& reason);
	int lineNumber() const { return line_no_; }

 private:
	int line_no_ = 0;
};

/** Parses a `.wf` stream; @p source names it in error messages. Throws WireFrameFormatError. */
WireFrame readWireFrame(std::istream& in, const std::string& source = "<stream>");

/** Loads a `.wf` file; name is set to the file stem. Throws std::runtime_error if unreadable. */
WireFrame loadWireFrame(const std::string& path);

/** Writes a model in the `.wf` format (exact round trip through readWireFrame). */
void writeWireFrame(const WireFrame& wf, std::ostream& out);

/** Saves to a file; throws std::runtime_error when the file cannot be written. */
void saveWireFrame(const WireFrame& wf, const std::string& path);

/** "object", "left_camera" or "c0". */
std::string frameName(WireFrameFrame f);

/** Inverse of frameName; throws std::invalid_argument for an unknown name. */
WireFrameFrame frameFromName(const std::string& name);

}  // namespace mrolr::model
