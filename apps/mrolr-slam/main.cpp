// mrolr-slam: vision-driven EKF-SLAM; the logic is mrolr::apps::SlamApp.
#include <mrolr/apps/SlamApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-slam",
	    [&]
	    {
		    mrolr::apps::SlamApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
