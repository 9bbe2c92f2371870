// mrolr-ros-robot: the mission as a ROS 1 node; the logic is mrolr::apps::RosRobotApp.
#include <mrolr/apps/RosRobotApp.h>
#include <mrolr/ros/Node.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-ros-robot",
	                            [&]
	                            {
		                            mrolr::apps::RosRobotApp app;
		                            app.initialize(mrolr::ros::initNode(argc, argv, "mrolr_robot",
		                                                             mrolr::ros::OnStopSignal::FlagOnly));
		                            return app.run(std::cout, std::cerr);
	                            });
}
