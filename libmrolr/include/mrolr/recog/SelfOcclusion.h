#pragma once
/** Self-occlusion of a wire-frame model seen from a camera (beyond the thesis, used by
 * verification): from one viewpoint only the front of an object can be seen, so a pose is judged
 * by the support of the model length that is expected visible, not of the whole model. The
 * object's solid is approximated by a discrete-orientation polytope (k-DOP: the intersection of
 * the half-spaces n·x <= max_i n·p_i over fixed directions n) that encloses the convex hull of
 * points sampled on the model's features; a sample is hidden when the segment from the camera to
 * it passes through that polytope shrunk by a margin. Model frame, millimetres. */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/InnerBalls.h>
#include <mrolr/recog/images/Limbs.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace mrolr::recog
{
class SelfOcclusion
{
 public:
	/** @p features_O model features (model frame, mm); @p margin_mm how far inside the enclosing
	 * polytope a sight line must pass to hide a sample (covers the polytope's excess over the
	 * hull and edges on the surface); @p directions number of polytope face directions. */
	explicit SelfOcclusion(const std::vector<Feature>& features_O, double margin_mm = 3,
	                       int directions = 100);

	/** Fraction in [0, 1] of each feature's samples (same order as the constructor's features)
	 * that a camera at @p c_O (model frame, mm) sees, judging by the object's own solid. */
	std::vector<double> visibleFractions(const Eigen::Vector3d& c_O) const;

	/** True when the segment from @p c_O to @p p_O crosses the shrunk polytope. */
	bool hidden(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** True when @p p_O is inside the shrunk polytope (inside the object's solid). */
	bool contains(const Eigen::Vector3d& p_O) const;

	/** As hidden(), but a point on the surface of one of the model's bodies of revolution (within
	 * the margin) is judged against those bodies' solids exactly (crossesSolid, shrunk by the
	 * margin): the polytope, convex, fills a bottle's neck and hides the ring where neck and
	 * shoulder meet, which the camera sees. Other points: hidden(). Used by the verification in
	 * the images; the 3D verification keeps hidden(). */
	bool hiddenOnBodies(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** True when the segment from @p c_O to a limb point @p p_O crosses the polytope of the
	 * features off the bodies' surfaces (a cup's handle in front of its side); never for a model
	 * that is all bodies. (The whole polytope cannot judge a limb: the sight ray grazes the body
	 * there, and the polytope does not follow its round surface.) */
	bool hiddenLimb(const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O) const;

	/** The terms of the sight tests that depend only on the camera centre c_O (model frame, mm):
	 * built once per pose and camera, then asked for every sample (hidden(const View&, ...)). */
	class View
	{
	 public:
		const Eigen::Vector3d& centre_O() const { return c_O_; }

	 private:
		friend class SelfOcclusion;
		static constexpr size_t kMaxFaces = 128;        ///< at most this many face directions
		using PerFace = std::array<double, kMaxFaces>;  // fixed: a View is made per pose
		/** Per polytope (whole, off the bodies): the faces the camera is outside of. */
		struct Faces
		{
			std::array<std::uint64_t, 2> outside = {0, 0};  ///< bit i: n_i·c_O > offset_i
			/** The same n faces, one array per term: normal, n·c, n·c − offset, offset. */
			PerFace nx, ny, nz, nc, gap, offset;
			size_t n = 0;
		};
		Eigen::Vector3d c_O_;
		PerFace nc_;  ///< n_i·c_O per face direction
		Faces all_, rest_;
		BallsSeen balls_;  ///< the whole polytope's inner balls, from c_O
		std::vector<BodySight> bodies_;
	};
	/** The camera-side terms for a camera at @p c_O. */
	View viewFrom(const Eigen::Vector3d& c_O) const;

	/** What the sight tests need to know of one point whatever the camera: the faces of the
	 * shrunk polytopes it lies outside of and the bodies of revolution it lies on. */
	struct PointSight
	{
		std::array<std::uint64_t, 2> outside_all = {0, 0}, outside_rest = {0, 0};
		std::uint64_t on_bodies = 0;  ///< bit k: on the surface of revolutionBodies()[k]
		OwnBall own;                  ///< inside the whole polytope, near the point (ownBall)
	};
	/** The PointSight of @p p_O (model frame, mm): computed once per model sample. */
	PointSight pointSight(const Eigen::Vector3d& p_O) const;

	/** hidden(), hiddenOnBodies(), hiddenLimb() from a View (and the point's PointSight): the
	 * same answers, faster. */
	bool hidden(const View& v, const Eigen::Vector3d& p_O) const;
	bool hidden(const View& v, const PointSight& ps, const Eigen::Vector3d& p_O) const;
	bool hiddenOnBodies(const View& v, const Eigen::Vector3d& p_O) const;
	bool hiddenOnBodies(const View& v, const PointSight& ps, const Eigen::Vector3d& p_O) const;
	bool hiddenLimb(const View& v, const Eigen::Vector3d& p_O) const;
	/** True when the point (@p ps) lies outside a face of the polytope that the camera of @p v
	 * is outside of too: hidden() says it is not hidden at its first, bitwise step. */
	static bool sharesOutsideFace(const View& v, const PointSight& ps);

	/** The model's bodies of revolution (revolutionBodiesOf the constructor's features), whose
	 * limbs the verification in the images adds at each pose (Limbs.h); the 3D verification
	 * does not use them. */
	const std::vector<RevolutionBody>& revolutionBodies() const { return bodies_; }

 private:
	std::vector<double> offsetsOf(const std::vector<std::vector<Eigen::Vector3d>>& pts,
	                              double margin_mm) const;
	/** Writes into @p f the faces of @p offsets the camera is outside of, from its n·c @p nc (in
	 * place: a Faces is 6 kB, and viewFrom copied two of them per View). */
	void facesFrom(const std::vector<double>& offsets, const View::PerFace& nc,
	               View::Faces& f) const;
	std::array<std::uint64_t, 2> outsideFaces(const std::vector<double>& offsets,
	                                          const Eigen::Vector3d& p_O) const;
	/** True when the segment from the camera to @p p_O enters one of the faces the camera is
	 * outside of (@p f) at @p t1 or later: gap >= t1 (nc − n·p) for some face. */
	static bool enteredLate(const View::Faces& f, double t1, const Eigen::Vector3d& p_O);
	/** True when the segment from the camera of @p v to @p p_O crosses the solid of one of the
	 * bodies of revolution @p ps lies on (crossesSolid). */
	bool crossesBodies(const View& v, const PointSight& ps, const Eigen::Vector3d& p_O) const;
	/** True when the segment from the camera of @p v to @p p_O (outside the faces @p p_outside)
	 * crosses the shrunk polytope. */
	bool crossesPolytope(const View& v, const Eigen::Vector3d& p_O,
	                     const std::array<std::uint64_t, 2>& p_outside,
	                     const OwnBall& own = OwnBall()) const;

	std::vector<Eigen::Vector3d> normals_;  ///< at most View::kMaxFaces
	std::vector<double> nx_, ny_, nz_;      ///< the same, one array per coordinate
	std::vector<double> offsets_;           ///< plane offsets, already shrunk by the margin
	InnerBalls balls_;  ///< inside the shrunk polytope: a quick proof that a sample is hidden
	std::vector<std::vector<Eigen::Vector3d>> samples_;                       ///< per feature
	std::vector<std::vector<std::array<std::uint64_t, 2>>> samples_outside_;  ///< their faces
	std::vector<RevolutionBody> bodies_;  ///< at most 64 (PointSight::on_bodies)
	std::vector<double> rest_offsets_;  ///< polytope of the features off the bodies (may be empty)
	double margin_mm_;
};

// The per-sample tests, inline: the image verification asks them of every sample at every pose,
// and a sample that shares an outside face with the camera (most of those in view) needs no call.
inline bool SelfOcclusion::sharesOutsideFace(const View& v, const PointSight& ps)
{
	const auto& out = ps.outside_all;
	return (out[0] & v.all_.outside[0]) | (out[1] & v.all_.outside[1]);
}

inline bool SelfOcclusion::hidden(const View& v, const PointSight& ps,
                                  const Eigen::Vector3d& p_O) const
{
	if (sharesOutsideFace(v, ps)) return false;
	return crossesPolytope(v, p_O, ps.outside_all, ps.own);
}

inline bool SelfOcclusion::hiddenOnBodies(const View& v, const PointSight& ps,
                                          const Eigen::Vector3d& p_O) const
{
	return ps.on_bodies ? crossesBodies(v, ps, p_O) : hidden(v, ps, p_O);
}

/** Points along a feature: a line's samples from end to end, a conic's around its rim (an ellipse
 * as a circle of the mean semi-axis: the feature keeps no major-axis direction). */
std::vector<Eigen::Vector3d> samplesOf(const Feature& f, int count);

/** @p n nearly uniform unit directions (a Fibonacci sphere). */
std::vector<Eigen::Vector3d> sphereDirections(int n);

}  // namespace mrolr::recog
