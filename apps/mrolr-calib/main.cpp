// mrolr-calib: stereo calibration from checkerboard pairs; the logic is mrolr::apps::CalibApp.
#include <mrolr/apps/CalibApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-calib",
	    [&]
	    {
		    mrolr::apps::CalibApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
