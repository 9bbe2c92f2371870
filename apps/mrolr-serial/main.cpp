// mrolr-serial: device emulators on pseudo-terminals and one-shot requests to serial devices; the
// logic is mrolr::apps::SerialApp.
#include <mrolr/apps/SerialApp.h>
#include <mrolr/util/Cli.h>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-serial",
	    [&]
	    {
		    mrolr::apps::SerialApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run();
	    });
}
