// mrolr-recognize: object recognition and pose; the logic is mrolr::apps::RecognizeApp.
#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-recognize",
	    [&]
	    {
		    mrolr::apps::RecognizeApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run(std::cout);
	    });
}
