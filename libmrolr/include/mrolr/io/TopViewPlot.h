#pragma once
/** A top view of W, as the thesis draws it (Fig. 4.2: z forward up the page, x to the left), in
 * metres: one plotting module for every tool that draws a run from above (mrolr-ekf-sim,
 * mrolr-slam, a mission's trajectory.png).
 *
 * The picture has equal scale on both axes, a grid at a round step (1, 2 or 5 × 10^k m) with its
 * values on the axes, a scale bar, a title, and the legend in its own panel to the right of the
 * data so that it never hides any. Uncertainty is drawn as 95 % ellipses: for a covariance C of
 * (z, x), the ellipse {d : dᵀ C⁻¹ d = χ²₂(0.95) = 5.991}. For a landmark's 3 × 3 covariance this is
 * the ellipse of its (z, x) marginal.
 *
 * Positions are (z, x) pairs in W, metres, named `zx` (the order of the thesis's x_v = (z, x, φ)).
 */
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mrolr::io
{
/** A marker for points: the shapes of cv::MarkerTypes, and a filled disc. */
enum class Marker
{
	Square,
	FilledSquare,
	Cross,
	TiltedCross,
	Diamond,
	Star,
	Disc
};

/** Colour (OpenCV's BGR) and line width in pixels. */
struct PlotStyle
{
	cv::Scalar bgr{0, 0, 0};
	int thickness_px = 2;
};

/** χ²₂(0.95): the squared Mahalanobis radius of a 95 % ellipse in two dimensions. */
constexpr double kChi2_95_2dof = 5.991464547107979;

/** The semi-axes (major, minor; metres) and the major axis's direction (a unit (z, x) vector) of
 * the 95 % ellipse of a (z, x) covariance. Negative eigenvalues (rounding) count as 0. */
struct Ellipse95
{
	double major_m = 0, minor_m = 0;
	Eigen::Vector2d major_axis_zx = Eigen::Vector2d::UnitX();
};
Ellipse95 ellipse95(const Eigen::Matrix2d& P_zx);

/** The (z, x) block of a covariance over (z, x, φ) (a vehicle's P_vv). */
Eigen::Matrix2d zxBlockOfVehicle(const Eigen::Matrix3d& P_vv);
/** The (z, x) marginal of a covariance over W's (x, y, z) (a landmark's P). */
Eigen::Matrix2d zxMarginalOfPoint(const Eigen::Matrix3d& P_xyz);

/** How data coordinates become pixels once the picture is laid out: equal scale, z up, x left. */
struct PlotFrame
{
	cv::Rect data_px;         ///< the data area in the image
	double px_per_m = 1;      ///< the scale, the same on both axes
	double z_top_m = 0;       ///< z at the data area's top edge
	double x_left_m = 0;      ///< x at the data area's left edge (x grows to the left)
	double grid_step_m = 1;   ///< spacing of the grid lines
	cv::Rect legend_px;       ///< the legend panel, outside data_px

	cv::Point2d toPixel(const Eigen::Vector2d& zx) const;
};

/** The grid step for a span: the round step (1, 2 or 5 × 10^k) that gives 4 to 10 intervals. */
double gridStep(double span_m);

class TopViewPlot
{
   public:
	/** @p title: what the reader needs to know which run this is (tool, world or mission, seed). */
	explicit TopViewPlot(std::string title);

	/** A polyline through the positions (one legend entry). */
	void addPath(const std::string& label, const std::vector<Eigen::Vector2d>& zx,
	             const PlotStyle& style);
	/** Points with a marker of @p size_px. */
	void addPoints(const std::string& label, const std::vector<Eigen::Vector2d>& zx, Marker marker,
	               const PlotStyle& style, int size_px = 10);
	/** A 95 % ellipse around each centre; @p P_zx[i] is centre i's (z, x) covariance (m²). With
	 * @p at_most > 0 only that many, evenly spaced along the list (a path's ellipses would
	 * otherwise cover it). Throws std::invalid_argument when the counts differ. */
	void addEllipses95(const std::string& label, const std::vector<Eigen::Vector2d>& centres_zx,
	                   const std::vector<Eigen::Matrix2d>& P_zx, const PlotStyle& style,
	                   size_t at_most = 0);
	/** Filled polygons (footprints of tables, obstacles). */
	void addPolygons(const std::string& label,
	                 const std::vector<std::vector<Eigen::Vector2d>>& polygons_zx,
	                 const PlotStyle& style);
	/** Makes sure the view holds this box (a room), whatever the items' extent. */
	void includeExtent(const Eigen::Vector2d& lo_zx, const Eigen::Vector2d& hi_zx);

	/** Lays the picture out: the data's extent with a margin, at most @p data_size_px on its longer
	 * side. */
	PlotFrame layout(int data_size_px = 800) const;
	/** Draws the picture. */
	cv::Mat render(int data_size_px = 800) const;
	/** render(), written as PNG; throws std::runtime_error naming @p png_path if it cannot be. */
	void write(const std::string& png_path, int data_size_px = 800) const;

	/** The footprint of a rectangle centred at @p centre_zx, turned by @p yaw_rad (its depth
	 * along the turned z, its length along the turned x), as a polygon for addPolygons. */
	static std::vector<Eigen::Vector2d> rectangle(const Eigen::Vector2d& centre_zx, double yaw_rad,
	                                              double depth_m, double length_m);

	struct Item
	{
		enum class Kind
		{
			Path,
			Points,
			Ellipses,
			Polygons
		} kind = Kind::Path;
		std::string label;
		PlotStyle style;
		Marker marker = Marker::Cross;
		int size_px = 10;
		std::vector<std::vector<Eigen::Vector2d>> zx;  ///< one entry per path/polygon; points: one
		std::vector<Eigen::Matrix2d> P_zx;
	};

   private:
	std::string title_;
	std::vector<Item> items_;
	bool has_extent_ = false;
	Eigen::Vector2d lo_zx_ = Eigen::Vector2d::Zero(), hi_zx_ = Eigen::Vector2d::Zero();
	void grow(const Eigen::Vector2d& zx);
};

}  // namespace mrolr::io
