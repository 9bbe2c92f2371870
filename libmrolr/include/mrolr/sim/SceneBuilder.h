#pragma once
/** The renderable lab: a world file turned into an MRPT OpenGL scene, with W expressed in MRPT axes
 * (x forward = thesis z, y left = thesis x, z up = thesis y; geometry/Frames.h), so the same scene
 * serves the stereo renderer and SceneViewer3D. */

#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/World.h>

#include <mrpt/opengl/COpenGLScene.h>

#include <map>
#include <string>

namespace mrolr::sim
{
/** The scene and the object definitions it was built from (by model name). */
struct LabScene
{
	mrpt::opengl::COpenGLScene::Ptr scene;
	std::map<std::string, world::ObjectShape> shapes;  ///< model name → definition
};

/** Reads the definitions of every object placed in @p w (from w.objects_dir/<model>.ini). Throws
 * world::WorldError naming the object section and the missing or malformed file. */
std::map<std::string, world::ObjectShape> loadObjectShapes(const world::World& w);

/** Builds the scene: room surfaces, landmark patches, tables, obstacles and objects (named
 * "object.<name>"). A world without [room] gets only its objects and patches, and point landmarks
 * are drawn as small white spheres when @p draw_point_landmarks is set (for worlds that have no
 * patches). */
LabScene buildLabScene(const world::World& w, bool draw_point_landmarks = false);
/** The same with the object definitions already read (model name → definition). */
LabScene buildLabScene(const world::World& w,
                       const std::map<std::string, world::ObjectShape>& shapes,
                       bool draw_point_landmarks = false);

}  // namespace mrolr::sim
