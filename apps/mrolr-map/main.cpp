// mrolr-map: a plan of a world from one drive; the logic is mrolr::apps::MapApp.
#include <mrolr/apps/MapApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-map",
	                            [&]
	                            {
		                            mrolr::apps::MapApp app;
		                            app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		                            return app.run(std::cout, std::cerr);
	                            });
}
