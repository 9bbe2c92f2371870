// mrolr-ekf-sim: Monte-Carlo runs of the EKF-SLAM simulator; the logic is mrolr::apps::EkfSimApp.
#include <mrolr/apps/EkfSimApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-ekf-sim",
	    [&]
	    {
		    mrolr::apps::EkfSimApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
