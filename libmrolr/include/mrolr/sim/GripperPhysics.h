#pragma once
/** What the RTX's gripper does to the world (world side; the robot only reads the jaw width).
 *
 * The gripper G (arm/GraspFeasibility.h: z_G the approach, y_G the closing axis) has two finger
 * plates, finger_width_mm along x_G, finger_length_mm along z_G centred on the grasp point and
 * finger_thickness_mm thick, their inner faces ±separation/2 from the grasp point along y_G.
 *  - Moving: every few millimetres of a move the plates are tested against the objects' solids
 *    and the tables. An object they enter is pushed along with the fingers; an object touched
 *    above knock_over_height_fraction of its height that is taller than it is wide falls over
 *    (onto its side, away from the push). A table entered stops the arm (hw::ArmBlocked).
 *  - Closing: an object is caught only if the open plates straddle it (do not enter its solid)
 *    and the closed jaw distance (JawWidth.h) matches the object's full width across the jaws'
 *    slab (its extent along y_G over |x_G| ≤ finger_width/2, any z_G) within compliance_mm. A
 *    chord of a cylinder taken short of (or past) its axis does not match: the object is
 *    squeezed out along the approach and the jaws close on nothing.
 *  - Opening: the object held drops straight down onto the highest support under its origin
 *    (the robot's deck, a table or the floor). A drop of at most kGentleDrop_mm leaves it
 *    standing; from higher, or released tilted, an object taller than knock_over_aspect × its
 *    width falls over.
 * Lengths mm in G and O, poses in W (thesis axes, metres). */
#include <mrolr/sim/JawWidth.h>
#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::sim
{
/** Section [sim_gripper]: the jaws' compliance and the pushing model (all keys optional). */
struct GripperPhysicsOptions
{
	double compliance_mm = 3;          ///< closed width may fall this short of the object's width
	double finger_thickness_mm = 8;    ///< each plate along y_G
	double sample_step_mm = 4;         ///< spacing of the points tested on the plates
	double motion_step_mm = 4;         ///< largest gripper travel between two tested poses
	double knock_over_height_fraction = 0.6;  ///< a push above this fraction of the height tips…
	double knock_over_aspect = 1.3;    ///< …an object whose height exceeds this × its width

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One thing the gripper did to the world, for eval (`eval.gripper_events`). */
struct GripperEvent
{
	enum class Kind
	{
		Held,       ///< closed on the object and holds it
		Slipped,    ///< closed on it, but not across its width: squeezed out
		Pushed,     ///< a finger entered it during a move: it moved with the finger
		KnockedOver,///< pushed high: it fell onto its side
		Table,      ///< a finger met a table: the arm stopped
		Released    ///< the jaws opened on it: it came to rest on what was under it
	};
	Kind kind = Kind::Held;
	std::string object;  ///< instance name ("" for the table)
	std::string detail;  ///< one readable line

	static const char* name(Kind k);
};

/** Samples of the two plates in G (mm) with inner faces ±separation_mm/2 apart. */
std::vector<Eigen::Vector3d> fingerPoints(const JawGeometry& jaws, double thickness_mm,
                                          double separation_mm, double step_mm);

/** The object's full width across the jaws' slab: its extent along y_G over |x_G| ≤
 * finger_width/2 and any z_G (mm); 0 when the slab misses it. */
double widthAcrossMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_OinG_mm,
                     const JawGeometry& jaws);

/** The robot's deck as a support: its top face's centre and axes in W (y up), half sizes (m). */
struct DeckSupport
{
	Eigen::Isometry3d T_TopInW = Eigen::Isometry3d::Identity();
	double half_x_m = 0, half_z_m = 0;
};

/** The objects and tables the gripper meets (the lab's poses are updated in place). */
class GripperPhysics
{
 public:
	/** @p objects: instance → T_OinW (m), updated by pushes; @p model_of: instance → model name
	 * in @p shapes. */
	GripperPhysics(const world::World& world, const std::map<std::string, world::ObjectShape>& shapes,
	               std::map<std::string, std::string> model_of, const JawGeometry& jaws,
	               const GripperPhysicsOptions& o, std::map<std::string, Eigen::Isometry3d>& objects);

	/** One tested pose of a move with jaw separation @p separation_mm, the gripper having moved
	 * from @p T_GinW_before: pushes or tips what the plates enter (except @p held). Returns the
	 * table the plates entered, if any (the caller stops the arm before this pose). */
	std::optional<std::string> step(const Eigen::Isometry3d& T_GinW_before,
	                                const Eigen::Isometry3d& T_GinW, double separation_mm,
	                                const std::string& held);

	/** Closes the jaws at @p T_GinW: the caught instance ("" for none) and the jaw distance. */
	struct Grip
	{
		std::string object;
		double width_mm = 0;
		Eigen::Isometry3d T_OinG = Eigen::Isometry3d::Identity();  ///< m
	};
	Grip close(const Eigen::Isometry3d& T_GinW);

	/** A release dropping this far or less leaves an upright object standing (mm). */
	static constexpr double kGentleDrop_mm = 25;
	/** The jaws opened on @p name: it drops onto the highest support under its origin, @p deck
	 * among them. Returns true when it came to rest on the deck. */
	bool release(const std::string& name, const DeckSupport& deck);

	const std::vector<GripperEvent>& events() const { return events_; }
	const JawGeometry& jaws() const { return jaws_; }
	const GripperPhysicsOptions& options() const { return o_; }
	void note(GripperEvent e) { events_.push_back(std::move(e)); }

 private:
	const world::ObjectShape& shapeOf(const std::string& name) const;
	/** Plate points of @p T_GinW inside instance @p name's solid (W, m). */
	std::vector<Eigen::Vector3d> inside(const std::string& name, const Eigen::Isometry3d& T_GinW,
	                                    const std::vector<Eigen::Vector3d>& points_G) const;
	/** The highest support under @p p_W (tables and the floor) at or below it: height and name. */
	std::pair<double, std::string> supportUnder(const Eigen::Vector3d& p_W) const;
	std::optional<std::string> tableEntered(const Eigen::Isometry3d& T_GinW,
	                                        const std::vector<Eigen::Vector3d>& points_G) const;
	void push(const std::string& name, const Eigen::Vector3d& contact_W, const Eigen::Vector3d& d_W);
	void knockOver(const std::string& name, const Eigen::Vector3d& d_W);
	/** Footprint width (min horizontal extent) and height of a shape (mm). */
	std::pair<double, double> widthAndHeight(const world::ObjectShape& shape) const;

	const world::World& world_;
	const std::map<std::string, world::ObjectShape>& shapes_;
	std::map<std::string, std::string> model_of_;
	JawGeometry jaws_;
	GripperPhysicsOptions o_;
	std::map<std::string, Eigen::Isometry3d>& objects_;
	std::map<std::string, bool> fallen_;
	std::vector<GripperEvent> events_;
};

}  // namespace mrolr::sim
