// mrolr-ros-lab: the simulated lab as a ROS 1 node; the logic is mrolr::apps::RosLabApp.
#include <mrolr/apps/RosLabApp.h>
#include <mrolr/ros/Node.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-ros-lab",
	                            [&]
	                            {
		                            mrolr::apps::RosLabApp app;
		                            app.initialize(mrolr::ros::initNode(argc, argv, "mrolr_lab"));
		                            return app.run(std::cout);
	                            });
}
