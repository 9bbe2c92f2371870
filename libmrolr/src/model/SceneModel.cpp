#include <mrolr/model/SceneModel.h>
#include <mrolr/geometry/PoseUnits.h>

#include <stdexcept>

namespace mrolr::model
{
WireFrame sceneToWireFrame(const stereo::StereoScene& scene)
{
	WireFrame wf;
	wf.frame = WireFrameFrame::LeftCamera;
	int id = 1;
	for (const auto& l : scene.lines) wf.lines.push_back({id++, l.p1, l.p2});
	for (const auto& c : scene.conics)
	{
		Conic3 k;
		k.id = id++;
		k.centre = c.centre;
		k.normal = c.normal;
		k.major = c.major;
		k.a = c.a;
		k.b = c.b;
		k.t1 = c.t1;
		k.t2 = c.t2;
		wf.conics.push_back(k);
	}
	return wf;
}

WireFrame transformWireFrame(const WireFrame& wf, const Eigen::Isometry3d& T, WireFrameFrame to)
{
	WireFrame out = wf;
	out.frame = to;
	const Eigen::Matrix3d R = T.linear();
	for (auto& l : out.lines)
	{
		l.p1 = T * l.p1;
		l.p2 = T * l.p2;
	}
	for (auto& c : out.conics)
	{
		c.centre = T * c.centre;
		c.normal = R * c.normal;
		c.major = R * c.major;
	}
	out.grasp.p_mm = T * out.grasp.p_mm;
	return out;
}

WireFrame leftCameraToC0(const WireFrame& wf_L, const geometry::BiSightHead& head,
                         const geometry::HeadAngles& angles)
{
	if (wf_L.frame != WireFrameFrame::LeftCamera)
		throw std::invalid_argument("leftCameraToC0 needs a wire-frame in frame left_camera");
	return transformWireFrame(wf_L, geometry::inMm(head.T_LinC0(angles)), WireFrameFrame::C0);
}

}  // namespace mrolr::model
