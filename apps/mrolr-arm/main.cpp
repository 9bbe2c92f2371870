// mrolr-arm: UMI RTX kinematics, IK and grasp chain; the logic is mrolr::apps::ArmApp.
#include <mrolr/apps/ArmApp.h>
#include <mrolr/util/Cli.h>

int main(int argc, char** argv)
{
	return mrolr::util::runMain(
	    "mrolr-arm",
	    [&]
	    {
		    mrolr::apps::ArmApp app;
		    app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		    return app.run();
	    });
}
