// mrolr-sim: the simulated lab; the logic is mrolr::apps::SimApp.
#include <mrolr/apps/SimApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-sim",
	    [&]
	    {
		    mrolr::apps::SimApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
