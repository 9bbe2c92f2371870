#include <cmath>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Config.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace mrolr::model
{
namespace
{
constexpr const char* kHeader = "# mrolr wire-frame 1";

/** Parser state for one file: the model so far and what the later lines are checked against. */
struct Parser
{
	std::string source;
	int line_no = 0;
	WireFrame wf;
	std::set<int> ids;
	bool seen_units = false, seen_frame = false;

	[[noreturn]] void fail(const std::string& why) const
	{
		throw WireFrameFormatError(source, line_no, why);
	}
};

std::vector<std::string> tokens(const std::string& line)
{
	std::istringstream ss(line.substr(0, line.find('#')));
	std::vector<std::string> out;
	for (std::string t; ss >> t;) out.push_back(t);
	return out;
}

double number(const Parser& p, const std::string& t, const char* what)
{
	double v = 0;
	if (!util::parseDouble(t, v))
		p.fail(std::string(what) + ": '" + t + "' is not a finite number");
	return v;
}

int positiveId(const Parser& p, const std::string& t, const char* what)
{
	const double v = number(p, t, what);
	if (v < 1 || v != std::floor(v) || v > std::numeric_limits<int>::max())
		p.fail(std::string(what) + ": '" + t + "' is not a positive integer id");
	return static_cast<int>(v);
}

void expectCount(const Parser& p, const std::vector<std::string>& tk, size_t n)
{
	if (tk.size() != n)
		p.fail("'" + tk[0] + "' needs " + std::to_string(n - 1) + " fields, got " +
		       std::to_string(tk.size() - 1));
}

Eigen::Vector3d vec3(const Parser& p, const std::vector<std::string>& tk, size_t i, const char* w)
{
	return {number(p, tk[i], w), number(p, tk[i + 1], w), number(p, tk[i + 2], w)};
}

int newId(Parser& p, const std::string& t)
{
	const int id = positiveId(p, t, "id");
	if (!p.ids.insert(id).second) p.fail("duplicate id " + std::to_string(id));
	return id;
}

void parseLine(Parser& p, const std::vector<std::string>& tk)
{
	expectCount(p, tk, 8);
	Line3 l;
	l.id = newId(p, tk[1]);
	l.p1 = vec3(p, tk, 2, "line endpoint");
	l.p2 = vec3(p, tk, 5, "line endpoint");
	if (l.length() <= 0) p.fail("line " + tk[1] + " has zero length");
	p.wf.lines.push_back(l);
}

/** Unit vector from the file; renormalised only when it is not already unit to 1e-12 so that a
 * written model reads back bit-exact. */
Eigen::Vector3d unitVector(const Parser& p, Eigen::Vector3d v, const char* what)
{
	const double n = v.norm();
	if (n < 1e-9) p.fail(std::string(what) + " is the zero vector");
	if (std::abs(n - 1.0) > 1e-12) v /= n;
	return v;
}

/** How far (the cosine between them) a conic's major axis may lean out of its plane and still be
 * taken as written with rounded numbers: four decimals on unit vectors give cosines up to about
 * 2e-4 between axes that are exactly perpendicular. */
constexpr double kRoundedPerpendicular = 1e-3;

/** The major axis put back into the conic's plane when rounding explains its lean (so a file
 * written with four decimals by another tool loads); a lean beyond that is an error naming it.
 * An axis already in its plane to 1e-12 is kept as read, so a written model reads back bit-exact. */
void inPlaneMajorAxis(const Parser& p, Conic3& c)
{
	const double lean = c.normal.dot(c.major);
	if (std::abs(lean) > kRoundedPerpendicular)
	{
		const double deg = 90.0 - std::acos(std::min(1.0, std::abs(lean))) * 180.0 / M_PI;
		p.fail("conic major axis is " + std::to_string(deg) + " deg out of its plane (rounding " +
		       "explains at most " + std::to_string(std::asin(kRoundedPerpendicular) * 180.0 / M_PI) +
		       " deg)");
	}
	if (std::abs(lean) > 1e-12) c.major = (c.major - lean * c.normal).normalized();
}

void checkConicShape(const Parser& p, const Conic3& c)
{
	if (!(c.b > 0) || c.a < c.b) p.fail("conic semi-axes must satisfy a >= b > 0");
	if (!(c.t2 > c.t1)) p.fail("conic arc needs t1 < t2");
}

void parseConic(Parser& p, const std::vector<std::string>& tk)
{
	expectCount(p, tk, 15);
	Conic3 c;
	c.id = newId(p, tk[1]);
	c.centre = vec3(p, tk, 2, "conic centre");
	c.normal = unitVector(p, vec3(p, tk, 5, "conic normal"), "conic normal");
	c.major = unitVector(p, vec3(p, tk, 8, "conic major axis"), "conic major axis");
	c.a = number(p, tk[11], "semi-axis a");
	c.b = number(p, tk[12], "semi-axis b");
	c.t1 = number(p, tk[13], "t1");
	c.t2 = number(p, tk[14], "t2");
	inPlaneMajorAxis(p, c);
	checkConicShape(p, c);
	p.wf.conics.push_back(c);
}

void parseGrasp(Parser& p, const std::vector<std::string>& tk)
{
	expectCount(p, tk, 7);
	if (p.wf.has_grasp) p.fail("second grasp line");
	p.wf.has_grasp = true;
	p.wf.grasp.p_mm = vec3(p, tk, 1, "grasp position");
	p.wf.grasp.yaw_deg = number(p, tk[4], "grasp yaw_deg");
	p.wf.grasp.pitch_deg = number(p, tk[5], "grasp pitch_deg");
	p.wf.grasp.roll_deg = number(p, tk[6], "grasp roll_deg");
}

/** Cliques are checked against ids when the whole file has been read (they may come first). */
void parseClique(Parser& p, const std::vector<std::string>& tk)
{
	if (tk.size() < 3) p.fail("'clique' needs FOCUS N ID1 ... IDN");
	Clique c;
	c.focus = positiveId(p, tk[1], "clique focus");
	const int n = positiveId(p, tk[2], "clique size N");
	if (tk.size() != static_cast<size_t>(n) + 3)
		p.fail("clique says N=" + tk[2] + " but lists " + std::to_string(tk.size() - 3) + " ids");
	for (size_t i = 3; i < tk.size(); ++i) c.members.push_back(positiveId(p, tk[i], "clique id"));
	p.wf.cliques.push_back(c);
}

void parseKeyValue(Parser& p, const std::vector<std::string>& tk)
{
	expectCount(p, tk, 2);
	if (tk[0] == "units")
	{
		if (tk[1] != "mm") p.fail("only 'units mm' is supported, got '" + tk[1] + "'");
		p.seen_units = true;
		return;
	}
	try
	{
		p.wf.frame = frameFromName(tk[1]);
	}
	catch (const std::invalid_argument& e)
	{
		p.fail(e.what());
	}
	p.seen_frame = true;
}

void parseRecord(Parser& p, const std::vector<std::string>& tk)
{
	const std::string& k = tk[0];
	if (k == "line") return parseLine(p, tk);
	if (k == "conic") return parseConic(p, tk);
	if (k == "grasp") return parseGrasp(p, tk);
	if (k == "clique") return parseClique(p, tk);
	if (k == "units" || k == "frame") return parseKeyValue(p, tk);
	p.fail("unknown record '" + k + "' (expected line, conic, grasp, clique, units or frame)");
}

void checkCliqueIds(const Parser& p)
{
	for (const auto& c : p.wf.cliques)
	{
		if (!p.ids.count(c.focus)) p.fail("clique focus " + std::to_string(c.focus) + " is no id");
		for (int m : c.members)
			if (!p.ids.count(m)) p.fail("clique member " + std::to_string(m) + " is no id");
	}
}
}  // namespace

WireFrameFormatError::WireFrameFormatError(const std::string& source, int line_no,
                                           const std::string& reason)
    : std::runtime_error(source + ":" + std::to_string(line_no) + ": " + reason), line_no_(line_no)
{
}

WireFrame readWireFrame(std::istream& in, const std::string& source)
{
	Parser p;
	p.source = source;
	std::string line;
	bool header = false;
	while (std::getline(in, line))
	{
		++p.line_no;
		if (!line.empty() && line.back() == '\r') line.pop_back();
		if (!header && tokens(line).empty() && line.rfind(kHeader, 0) != 0) continue;
		if (!header && line.rfind(kHeader, 0) != 0)
			p.fail(std::string("expected '") + kHeader + "'");
		if (!header)
			header = true;
		else if (const auto tk = tokens(line); !tk.empty())
			parseRecord(p, tk);
	}
	if (!header) p.fail(std::string("empty file: no '") + kHeader + "' header");
	if (!p.seen_units) p.fail("missing 'units mm' line");
	if (!p.seen_frame) p.fail("missing 'frame' line");
	checkCliqueIds(p);
	return p.wf;
}

WireFrame loadWireFrame(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error("cannot open wire-frame file '" + path + "'");
	WireFrame wf = readWireFrame(f, path);
	wf.name = std::filesystem::path(path).stem().string();
	return wf;
}

namespace
{
void put(std::ostream& out, const Eigen::Vector3d& v)
{
	out << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
}

void writeConic(const Conic3& c, std::ostream& out)
{
	out << "conic " << c.id;
	put(out, c.centre);
	put(out, c.normal);
	put(out, c.major);
	out << ' ' << c.a << ' ' << c.b << ' ' << c.t1 << ' ' << c.t2 << '\n';
}

void writeClique(const Clique& c, std::ostream& out)
{
	out << "clique " << c.focus << ' ' << c.members.size();
	for (int m : c.members) out << ' ' << m;
	out << '\n';
}
}  // namespace

void writeWireFrame(const WireFrame& wf, std::ostream& out)
{
	const auto old_prec = out.precision(std::numeric_limits<double>::max_digits10);
	out << kHeader << "\nunits mm\nframe " << frameName(wf.frame) << '\n';
	for (const auto& l : wf.lines)
	{
		out << "line " << l.id;
		put(out, l.p1);
		put(out, l.p2);
		out << '\n';
	}
	for (const auto& c : wf.conics) writeConic(c, out);
	if (wf.has_grasp)
	{
		const auto& g = wf.grasp;
		out << "grasp";
		put(out, g.p_mm);
		out << ' ' << g.yaw_deg << ' ' << g.pitch_deg << ' ' << g.roll_deg << '\n';
	}
	for (const auto& c : wf.cliques) writeClique(c, out);
	out.precision(old_prec);
}

void saveWireFrame(const WireFrame& wf, const std::string& path)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write wire-frame file '" + path + "'");
	writeWireFrame(wf, f);
	if (!f) throw std::runtime_error("error while writing wire-frame file '" + path + "'");
}

std::string frameName(WireFrameFrame f)
{
	switch (f)
	{
		case WireFrameFrame::Object:
			return "object";
		case WireFrameFrame::LeftCamera:
			return "left_camera";
		case WireFrameFrame::C0:
			return "c0";
	}
	return "object";
}

WireFrameFrame frameFromName(const std::string& name)
{
	if (name == "object") return WireFrameFrame::Object;
	if (name == "left_camera") return WireFrameFrame::LeftCamera;
	if (name == "c0") return WireFrameFrame::C0;
	throw std::invalid_argument("unknown frame '" + name +
	                            "' (expected object, left_camera or c0)");
}

}  // namespace mrolr::model
