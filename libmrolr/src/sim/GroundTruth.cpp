#include <mrolr/sim/GroundTruth.h>
#include <mrolr/sim/Placement.h>

#include <cmath>

namespace mrolr::sim
{
namespace
{
bool inFront(const geometry::BiSightHead& head, const Eigen::Vector3d& p_C0,
             const geometry::HeadAngles& a)
{
	return head.pointInCamera(geometry::Side::Left, p_C0, a).z() > 0.05 &&
	       head.pointInCamera(geometry::Side::Right, p_C0, a).z() > 0.05;
}

/** True unless the rendered depth at the landmark's left pixel is clearly nearer than it. */
bool unoccluded(const StereoFrame& f, const LandmarkView& v, double depth_m)
{
	const int u = int(std::lround(v.uL)), r = int(std::lround(v.vL));
	const float d = f.depth_left_m(r, u);
	return d <= 0 || d > depth_m - (0.03 + 0.02 * depth_m);
}

LandmarkView viewOf(const world::Landmark& l, const geometry::BiSightHead& head,
                    const Eigen::Isometry3d& T_C0inW, const geometry::HeadAngles& a,
                    const StereoFrame* f)
{
	LandmarkView v;
	v.name = l.name;
	v.known = l.known;
	v.p_LinW = l.p_LinW;
	v.p_LinC0 = T_C0inW.inverse() * l.p_LinW;
	if (!inFront(head, v.p_LinC0, a)) return v;
	const auto px = head.project(v.p_LinC0, a);
	v.uL = px.uL, v.vL = px.vL, v.uR = px.uR, v.vR = px.vR;
	const auto& cam = head.camera();
	v.visible = cam.isInImage({v.uL, v.vL}) && cam.isInImage({v.uR, v.vR});
	if (v.visible && f)
		v.visible = unoccluded(*f, v, head.pointInCamera(geometry::Side::Left, v.p_LinC0, a).z());
	return v;
}
}  // namespace

std::vector<LandmarkView> landmarkViews(const world::World& w, const geometry::BiSightHead& head,
                                        const Eigen::Isometry3d& T_C0inW,
                                        const geometry::HeadAngles& angles,
                                        const StereoFrame* frame)
{
	std::vector<LandmarkView> out;
	for (const auto& l : w.landmarks) out.push_back(viewOf(l, head, T_C0inW, angles, frame));
	return out;
}

std::vector<ObjectView> objectViews(const world::World& w, const geometry::BiSightHead& head,
                                    const Eigen::Isometry3d& T_C0inW,
                                    const geometry::HeadAngles& angles)
{
	std::vector<ObjectView> out;
	const Eigen::Isometry3d T_LinW = T_C0inW * head.T_LinC0(angles);
	for (const auto& o : w.objects)
	{
		ObjectView v;
		v.name = o.name;
		v.model = o.model;
		const Eigen::Isometry3d T_OinW_ = T_OinW(w, o);
		v.T_OinL = T_LinW.inverse() * T_OinW_;
		v.T_OinC0 = T_C0inW.inverse() * T_OinW_;
		const Eigen::Vector3d p = v.T_OinL.translation();
		if (p.z() > 0.05)
		{
			const Eigen::Vector2d uv = head.camera().project(p);
			v.uL = uv.x(), v.vL = uv.y();
			v.visible = head.camera().isInImage(uv);
		}
		out.push_back(v);
	}
	return out;
}

}  // namespace mrolr::sim
