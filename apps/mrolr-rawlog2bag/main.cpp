// mrolr-rawlog2bag: an MROLR rawlog as a ROS 1 bag; the logic is mrolr::apps::Rawlog2BagApp.
#include <mrolr/apps/Rawlog2BagApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-rawlog2bag",
	                            [&]
	                            {
		                            mrolr::apps::Rawlog2BagApp app;
		                            app.initialize(std::vector<std::string>(argv, argv + argc));
		                            return app.run(std::cout, std::cerr);
	                            });
}
