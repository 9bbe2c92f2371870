// mrolr-ros-bag: a mission's topics into a bag; the logic is mrolr::apps::RosBagApp.
#include <mrolr/apps/RosBagApp.h>
#include <mrolr/ros/Node.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-ros-bag",
	                            [&]
	                            {
		                            mrolr::apps::RosBagApp app;
		                            app.initialize(mrolr::ros::initNode(argc, argv, "mrolr_bag"));
		                            return app.run(std::cout);
	                            });
}
