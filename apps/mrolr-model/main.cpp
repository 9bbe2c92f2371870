// mrolr-model: wire-frame models from stereo; the logic is mrolr::apps::ModelApp.
#include <mrolr/apps/ModelApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-model",
	    [&]
	    {
		    mrolr::apps::ModelApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
