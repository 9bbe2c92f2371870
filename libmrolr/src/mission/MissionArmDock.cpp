// The arm's platform docks with the base once the object is found and is de-coupled before the
// drive home (thesis 7.0: the RTX on its caster platform, manually docked and de-coupled).
#include <mrolr/hw_serial/SerialError.h>
#include "MissionImpl.h"

namespace mrolr::mission
{
void Mission::Impl::dockArm()
{
	dev.arm->dock(true);
	r.arm_docked = true;
	self->setJoints(dev.arm->joints());
	self->setDocked(true);
	r.timeline.note("the arm's platform docked with the base");
}

void Mission::Impl::undockArm()
{
	if (!r.arm_docked) return;
	if (r.retrieved && !r.place.placed)
	{
		r.arm_docked_home = true;
		r.timeline.note("the arm stays docked: it holds the object home");
		return;
	}
	auto refused = [this](const std::string& why)  // the arm rides home docked
	{
		r.arm_docked_home = true;
		r.arm_undock_refused = why;
		r.timeline.note("the arm stays docked: de-coupling refused: " + why);
	};
	try
	{
		if (dev.arm->gripperClosed()) dev.arm->setGripper(false);  // closed on nothing
		dev.arm->dock(false);
		self->setDocked(false);
		r.timeline.note("the arm's platform de-coupled");
	}
	catch (const hw_serial::SerialDeviceError& e)
	{
		if (e.kind() != hw_serial::SerialDeviceError::Kind::Refused) throw;  // a dead line stops it
		refused(e.what());
	}
	catch (const std::logic_error& e)
	{
		refused(e.what());
	}
}

}  // namespace mrolr::mission
