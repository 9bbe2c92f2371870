// mrolr-mission: the fetch mission; the logic is mrolr::apps::MissionApp.
#include <mrolr/apps/MissionApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-mission",
	    [&]
	    {
		    mrolr::apps::MissionApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout, std::cerr);
	    });
}
