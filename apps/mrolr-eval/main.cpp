// mrolr-eval: a run's report checked against the world's truth; the logic is mrolr::apps::EvalApp.
#include <mrolr/apps/EvalApp.h>
#include <mrolr/util/Cli.h>

#include <iostream>

int main(int argc, char** argv)
{
	return mrolr::util::runMain("mrolr-eval",
	                            [&]
	                            {
		                            mrolr::apps::EvalApp app;
		                            app.initialize(mrolr::util::argsWithNegativeNumbersProtected(argc, argv));
		                            return app.run(std::cout);
	                            });
}
