#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/Placement.h>
#include <mrolr/sim/SceneWireFrame.h>

namespace mrolr::sim
{
namespace
{
/** The 12 edges of a table top (the box SceneBuilder draws: 30 mm thick), W in mm. */
void addTableTop(const world::World& w, const world::Table& t, model::WireFrame& out)
{
	const double top = 0.03;
	const Eigen::Matrix3d R = R_aboutVertical(t.yaw_deg * M_PI / 180);
	const double y1 = w.room.floorY() + t.top_height_m, y0 = y1 - top;
	auto corner = [&](int i) -> Eigen::Vector3d  // bit 0: x side, bit 1: z side, bit 2: top
	{
		const Eigen::Vector3d local((i & 1 ? 0.5 : -0.5) * t.length_m, (i & 4) ? y1 : y0,
		                            (i & 2 ? 0.5 : -0.5) * t.depth_m);
		const Eigen::Vector3d off = R * Eigen::Vector3d(local.x(), 0, local.z());
		return Eigen::Vector3d(t.x_m + off.x(), local.y(), t.z_m + off.z()) * 1000.0;
	};
	for (int i = 0; i < 8; ++i)
		for (int bit : {1, 2, 4})
			if (!(i & bit)) out.lines.push_back({0, corner(i), corner(i | bit)});
}

void addObject(const world::World& w, const world::PlacedObject& o,
               const std::map<std::string, world::ObjectShape>& shapes, model::WireFrame& out)
{
	const auto s = shapes.find(o.model);
	if (s == shapes.end())
		throw world::WorldError(w.path + ": object '" + o.name + "': no definition of model '" +
		                        o.model + "'");
	const Eigen::Isometry3d T = geometry::inMm(T_OinW(w, o));
	const auto wf =
	    model::transformWireFrame(objectWireFrame(s->second), T, model::WireFrameFrame::Object);
	out.lines.insert(out.lines.end(), wf.lines.begin(), wf.lines.end());
	out.conics.insert(out.conics.end(), wf.conics.begin(), wf.conics.end());
}
}  // namespace

model::WireFrame tableSceneWireFrame(const world::World& w,
                                     const std::map<std::string, world::ObjectShape>& shapes,
                                     SceneParts parts)
{
	model::WireFrame out;
	out.name = "table_scene";
	if (parts == SceneParts::ObjectsAndTables)
		for (const auto& t : w.tables) addTableTop(w, t, out);
	for (const auto& o : w.objects) addObject(w, o, shapes, out);
	int id = 1;
	for (auto& l : out.lines) l.id = id++;
	for (auto& c : out.conics) c.id = id++;
	return out;
}

model::WireFrame tableSceneInCamera(const world::World& w,
                                    const std::map<std::string, world::ObjectShape>& shapes,
                                    const Eigen::Isometry3d& T_CinW, SceneParts parts)
{
	return model::transformWireFrame(tableSceneWireFrame(w, shapes, parts),
	                                 geometry::inMm(T_CinW.inverse()),
	                                 model::WireFrameFrame::LeftCamera);
}

}  // namespace mrolr::sim
