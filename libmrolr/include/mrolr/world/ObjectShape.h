#pragma once
/** Geometric definition of a database object, `datasets/objects/<name>.ini` (docs/sim.md "Object
 * definitions"): boxes, cylinders, cones and a cup handle with colours, plus stroke-letter markings
 * (the alphabet cube of thesis 6.1) and the grasp point (6.1(b)). Coordinates are millimetres in
 * the object model frame O of thesis 6.1: z up along the turntable axis, origin at the centre of
 * the object's footprint on the table, x and y horizontal. */

#include <mrolr/world/WorldIni.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mrolr::world
{
/** One solid part. Box: `size_mm` (x, y, z), yawed by `yaw_deg` about z. Cylinder/Cone: a frustum
 * of height `height_mm` with radii `radius_bottom_mm`, `radius_top_mm`, axis along z. Handle: a
 * half ring of rectangular section in the plane spanned by z and the horizontal direction at
 * `yaw_deg` from x, centre line radius `radius_mm`, radial thickness `thickness_mm`, width
 * `width_mm` across the plane. `base_mm` is the centre of the bottom face (handle: the ring's
 * centre). */
struct ShapePart
{
	enum class Kind
	{
		Box,
		Frustum,
		Handle
	};
	std::string name;
	Kind kind = Kind::Box;
	Eigen::Vector3d base_mm = Eigen::Vector3d::Zero();
	double yaw_deg = 0;
	Eigen::Vector3d size_mm{50, 50, 50};                            ///< box only
	double height_mm = 0, radius_bottom_mm = 0, radius_top_mm = 0;  ///< frustum only
	double radius_mm = 0, thickness_mm = 0, width_mm = 0;           ///< handle only
	Eigen::Vector3d colour{0.8, 0.8, 0.8};                          ///< RGB 0..1
};

/** A stroke letter drawn on a flat face of a box part: the face is named by its outward normal
 * (+x, -x, +y, -y, +z) in the part's axes; letters are `height_mm` tall, centred on the face. */
struct Marking
{
	std::string name;
	std::string part;
	std::string face;
	char letter = 'A';
	double height_mm = 30;
	double stroke_mm = 4;
	Eigen::Vector3d colour{0.05, 0.05, 0.05};
};

/** A whole object definition. */
struct ObjectShape
{
	std::string name;
	std::string path;
	std::vector<ShapePart> parts;
	std::vector<Marking> markings;
	bool has_grasp = false;
	Eigen::Vector3d grasp_p_mm = Eigen::Vector3d::Zero();
	double grasp_yaw_deg = 0, grasp_pitch_deg = 0, grasp_roll_deg = 0;

	/** Reads an object definition; throws WorldError naming file, line, section, key and value. */
	static ObjectShape load(const std::string& path);
	static ObjectShape parse(const std::string& text, const std::string& path = "<memory>");
	const ShapePart* findPart(const std::string& name) const;
	/** Height of the highest point above the base (mm), for placing and framing. */
	double heightMm() const;
};

}  // namespace mrolr::world
