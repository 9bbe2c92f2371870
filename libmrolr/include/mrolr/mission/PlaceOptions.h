#pragma once
/** Section [place] of a mission file: putting the retrieved object down on the robot's deck
 * (mission/DeckPlacement.h). Every key is optional. */
#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::mission
{
/** Section [place] (every key optional). */
struct PlaceOptions
{
	bool enabled = true;        ///< false: the object stays in the gripper on the way home
	double drop_mm = 5;         ///< the object's bottom above the deck when the jaws open
	double margin_mm = 15;      ///< clearance kept from the deck and the mast
	double self_margin_mm = 5;  ///< clearance kept between the arm's own parts
	double grid_step_mm = 40;   ///< spacing of the candidate spots on the deck
	double yaw_step_deg = 45;   ///< the object turned about the vertical in these steps
	double check_step_mm = 10;  ///< largest travel between two tested poses of a move
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::mission
