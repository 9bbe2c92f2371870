#pragma once
/** The exact wire-frame of a table scene (the reference for the quality of single-view scene models, docs/model.md): every
 * placed object's wire-frame (objectWireFrame, moved by T_OinW) and the 12 edges of every table
 * top, in W (thesis axes: x left, y up, z forward) in millimetres. Occluding contours of curved
 * surfaces are view-dependent and not part of it. */

#include <mrolr/model/WireFrame.h>
#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/World.h>

#include <Eigen/Geometry>

#include <map>
#include <string>

namespace mrolr::sim
{
/** What a table scene's wire-frame holds. */
enum class SceneParts
{
	Objects,           ///< the placed objects only (what the recogniser looks for)
	ObjectsAndTables,  ///< and the 12 edges of every table top
};

/** Wire-frame of the objects (and table tops) of @p w in W, mm (frame label: object; ids 1, 2,
 * …). @p shapes: object definitions by model name (LabScene::shapes). Throws world::WorldError for
 * an object whose model is missing from @p shapes or whose table does not exist. */
model::WireFrame tableSceneWireFrame(const world::World& w,
                                     const std::map<std::string, world::ObjectShape>& shapes,
                                     SceneParts parts);

/** The same wire-frame seen from a camera at @p T_CinW (metres, thesis axes): frame left_camera. */
model::WireFrame tableSceneInCamera(const world::World& w,
                                    const std::map<std::string, world::ObjectShape>& shapes,
                                    const Eigen::Isometry3d& T_CinW, SceneParts parts);

}  // namespace mrolr::sim
