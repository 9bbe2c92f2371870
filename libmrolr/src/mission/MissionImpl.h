#pragma once
// The mission's state (private to the mission area): Mission.cpp runs the stages,
// MissionRetrieve.cpp the retrieval (docking, dock calibration, grasp).
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionStereoHead.h>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace mrolr::mission
{
struct Mission::Impl
{
	const MissionOptions& o;
	MissionResult r;
	RobotDevices dev;
	SimulatedSensors sensors;
	model::WireFrame target;
	std::unique_ptr<Navigator> nav;
	std::unique_ptr<ObjectSearch> search;
	std::unique_ptr<ObstacleAvoidance> obstacles;  ///< obstacle mode
	std::unique_ptr<MissionStereoHead> nav_head;   ///< landmark_sensor = images
	std::unique_ptr<SelfModel> self;               ///< the arm in the head's view
	std::function<void(const std::string&, const PathSample&)>* progress = nullptr;
	std::atomic<bool>* stop_flag = nullptr;
	DecisionLog* decisions = nullptr;
	bool render_failed = false;
	hw::ArmJoints parked{};  ///< the arm's joints when the mission began: where it parks

	Impl(const MissionOptions& opts, RobotDevices d, SimulatedSensors s);
	hw::StereoImages grabStereo(StereoShot::Purpose purpose = StereoShot::Purpose::Table);
	SearchView reconstructedView(const geometry::HeadAngles& angles);
	SearchView simulatedView(const geometry::HeadAngles& angles);
	void attachObstacleMode();
	void stopSafely(const std::string& why);
	void runStages();
	void loadTarget();
	void navigate();
	bool searchStation(const NamedPose& station);
	void retrieve();
	void goHome();
	void finish();
	bool clearOfWalls(const Eigen::Vector3d& xv) const;
	Eigen::Isometry3d inW(const Eigen::Isometry3d& T_OinC0_mm, const Eigen::Vector3d& xv) const;
	Eigen::Isometry3d predictedInC0(const Eigen::Isometry3d& T_OinW_m,
	                                const Eigen::Vector3d& xv) const;
	std::optional<Sighting> dockAndReobserve(const Retrieval& retrieval,
	                                                  const PlanTable& table,
	                                                  const Eigen::Isometry3d& T_OinW_m,
	                                                  double top_height_m);
	std::optional<Sighting> reobserveAt(const Eigen::Isometry3d& T_OinC0_mm);
	/** The held object put down on the deck (DeckPlacement.h), the arm parked again. */
	void placeOnBoard(const Eigen::Isometry3d& T_C0inA_mm);
	/** The arm's platform docked with the base where it stands (thesis 7.0), or de-coupled again
	 * after the retrieval unless it holds the object (MissionArmDock.cpp). */
	void dockArm();
	void undockArm();
	/** T_C0inA measured with the hand's marker where the base stands (DockCalibration.h). */
	void calibrateDock(Retrieval& retrieval, const Eigen::Isometry3d& T_OinC0_mm,
	                   double top_height_m);
};


}  // namespace mrolr::mission
