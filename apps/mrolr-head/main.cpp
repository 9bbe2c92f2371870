// mrolr-head: BiSight head geometry from the command line; the logic is mrolr::apps::HeadApp.
#include <mrolr/apps/HeadApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-head",
	    [&]
	    {
		    mrolr::apps::HeadApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
