#include <mrolr/stereo/EdgeOnRims.h>
#include <mrolr/util/OptionsBinder.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>

namespace mrolr::stereo
{
namespace
{
/** Candidate tangent points at end @p q of rim piece @p p, nearest first: where the piece's line
 * meets the image of each steep 3D line passing within corner_radius_px of q (3D, mm in L), and
 * which line. */
std::vector<std::pair<Eigen::Vector3d, size_t>> tangentPoints(const ImagePiece& p, cv::Point2d q,
                                                              const std::vector<LineFit3>& lines,
                                                              const Eigen::Vector3d& up_L,
                                                              const Rectifier& rect,
                                                              const EdgeOnRimOptions& o)
{
	std::vector<std::pair<double, std::pair<Eigen::Vector3d, size_t>>> found;
	for (size_t k = 0; k < lines.size(); ++k)
	{
		const LineFit3& l = lines[k];
		const Eigen::Vector3d dir = l.p2 - l.p1;
		if (dir.norm() < 1 || std::abs(dir.normalized().dot(up_L)) < o.min_steepness) continue;
		if (l.p1.z() <= 0 || l.p2.z() <= 0) continue;
		const cv::Point2d u1 = rect.leftPixelOf(l.p1), u2 = rect.leftPixelOf(l.p2);
		const double len = cv::norm(u2 - u1);
		const auto x = len > 1 ? lineIntersection(p.a, p.b, u1, u2) : std::nullopt;
		if (!x) continue;
		// near the end, or on the piece's line beyond it (the rim's edge may fade before the
		// silhouette where its two sides have the same grey)
		const cv::Point2d out_dir = (q - 0.5 * (p.a + p.b)) / cv::norm(q - 0.5 * (p.a + p.b));
		const double beyond = (*x - q).dot(out_dir);
		if (cv::norm(*x - q) > o.corner_radius_px && (beyond <= 0 || beyond > o.max_extension_px))
			continue;
		const double t = (*x - u1).dot(u2 - u1) / (len * len);
		if (t < -o.corner_radius_px / len || t > 1 + o.corner_radius_px / len) continue;
		const double d1 = rect.disparityOf(l.p1), d2 = rect.disparityOf(l.p2);
		found.push_back(
		    {cv::norm(*x - q), {rect.pointInLeftCamera(x->x, x->y, d1 + t * (d2 - d1)), k}});
	}
	std::stable_sort(found.begin(), found.end(),
	                 [](const auto& x, const auto& y) { return x.first < y.first; });
	std::vector<std::pair<Eigen::Vector3d, size_t>> out;
	for (const auto& f : found) out.push_back(f.second);
	return out;
}

/** RMS image distance (px) of the piece's edgels from circle @p c's image (360 samples). */
double imageResidual(const ConicFit3& c, const std::vector<cv::Point2d>& px, const Rectifier& rect)
{
	std::vector<cv::Point2d> ring;
	for (int i = 0; i < 360; ++i)
		if (const Eigen::Vector3d x = c.pointAt(i * M_PI / 180); x.z() > 1)
			ring.push_back(rect.leftPixelOf(x));
	if (ring.size() < 360 || px.empty()) return 1e9;
	double sum = 0;
	for (const auto& q : px)
	{
		double d = 1e18;
		for (size_t i = 0; i < ring.size(); ++i)
		{
			const cv::Point2d a = ring[i], ab = ring[(i + 1) % ring.size()] - a;
			const double t = std::clamp((q - a).dot(ab) / std::max(ab.dot(ab), 1e-12), 0.0, 1.0);
			d = std::min(d, cv::norm(a + t * ab - q));
		}
		sum += d * d;
	}
	return std::sqrt(sum / px.size());
}

/** The circle through tangent points @p pl, @p pr seen from the camera at L's origin, or nothing
 * when the chord is not horizontal and square to the view, or the radius is out of range. */
std::optional<ConicFit3> circleOfTangents(const Eigen::Vector3d& pl, const Eigen::Vector3d& pr,
                                          const Eigen::Vector3d& up, const EdgeOnRimOptions& o)
{
	const Eigen::Vector3d chord = pr - pl, m = 0.5 * (pl + pr);
	const double half = 0.5 * chord.norm();
	Eigen::Vector3d h = m - m.dot(up) * up;  // horizontal direction from the camera to the chord
	const double D = h.norm();
	if (half < 1e-6 || D < 1e-6) return std::nullopt;
	h /= D;
	if (std::abs(chord.normalized().dot(up)) > std::sin(o.max_chord_tilt_deg * M_PI / 180) ||
	    std::abs(chord.normalized().dot(h)) > o.max_chord_view_cos)
		return std::nullopt;
	if (half >= 0.9 * D) return std::nullopt;
	const double r = half / std::sqrt(1 - (half / D) * (half / D));
	if (r < o.min_radius_mm || r > o.max_radius_mm) return std::nullopt;
	ConicFit3 c;
	c.centre = m + (r * r / D) * h;
	c.normal = up;
	c.major = h;
	c.a = c.b = r;
	c.t1 = 0;
	c.t2 = 2 * M_PI;
	return c;
}

bool covered(const ConicFit3& c, const std::vector<ConicFit3>& existing)
{
	return std::any_of(existing.begin(), existing.end(),
	                   [&](const ConicFit3& k)
	                   {
		                   return (k.centre - c.centre).norm() <= 0.5 * c.a &&
		                          std::abs(k.a - c.a) <= 0.2 * c.a;
	                   });
}
}  // namespace

std::vector<ConicFit3> edgeOnRims(const std::vector<EdgeString>& left_strings,
                                  const std::vector<ImagePiece>& left_pieces,
                                  const std::vector<LineFit3>& lines,
                                  const std::vector<ConicFit3>& existing,
                                  const Eigen::Vector3d& up_L, const Rectifier& rect,
                                  const EdgeOnRimOptions& o)
{
	std::vector<ConicFit3> out;
	const Eigen::Vector3d up = up_L.normalized();
	for (const auto& p : left_pieces)
	{
		const cv::Point2d v = p.b - p.a;
		if (!p.is_line ||
		    std::abs(v.y) > std::tan(o.max_image_deg * M_PI / 180) * std::abs(v.x))
			continue;
		const cv::Point2d left_end = p.a.x <= p.b.x ? p.a : p.b,
		                  right_end = p.a.x <= p.b.x ? p.b : p.a;
		const auto px = piecePoints(left_strings, p);
		std::optional<ConicFit3> c;
		for (const auto& tl : tangentPoints(p, left_end, lines, up, rect, o))
		{
			for (const auto& tr : tangentPoints(p, right_end, lines, up, rect, o))
			{
				if (tl.second == tr.second) continue;
				c = circleOfTangents(tl.first, tr.first, up, o);
				if (c && (covered(*c, existing) || covered(*c, out) ||
				          imageResidual(*c, px, rect) > o.max_residual_px))
					c.reset();
				if (c) break;
			}
			if (c) break;
		}
		if (!c) continue;
		c->edgels = static_cast<int>(p.hi - p.lo);
		out.push_back(*c);
	}
	return out;
}

namespace
{
using O = EdgeOnRimOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& edgeOnRimOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .flag("edge_on_rims", &O::enabled, kOpt)
	    .number("edge_on_rim_max_image_deg", &O::max_image_deg, 0, 45, kOpt)
	    .number("edge_on_rim_corner_radius_px", &O::corner_radius_px, 0, 50, kOpt)
	    .number("edge_on_rim_max_extension_px", &O::max_extension_px, 0, 500, kOpt)
	    .number("edge_on_rim_min_steepness", &O::min_steepness, 0, 1, kOpt)
	    .number("edge_on_rim_max_chord_tilt_deg", &O::max_chord_tilt_deg, 0, 90, kOpt)
	    .number("edge_on_rim_max_chord_view_cos", &O::max_chord_view_cos, 0, 1, kOpt)
	    .number("edge_on_rim_max_residual_px", &O::max_residual_px, 0.05, 20, kOpt)
	    .number("edge_on_rim_min_radius_mm", &O::min_radius_mm, 0, 1e4, kOpt)
	    .number("edge_on_rim_max_radius_mm", &O::max_radius_mm, 0, 1e5, kOpt);
	return b;
}
}  // namespace

void EdgeOnRimOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                         const std::string& section)
{
	edgeOnRimOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "edge_on_rim_max_radius_mm", max_radius_mm, min_radius_mm,
	                     1e5);
}

void EdgeOnRimOptions::dump(std::ostream& out) const
{
	edgeOnRimOptionsBinder().dump(out, *this);
}

}  // namespace mrolr::stereo
