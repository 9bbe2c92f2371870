#include <mrolr/apps/SimApp.h>

#include <stdexcept>

namespace mrolr::apps
{
int SimApp::runRecording(std::ostream&)
{
	throw std::runtime_error("recording: work in progress");
}
int SimApp::runTurntable(std::ostream&)
{
	throw std::runtime_error("turntable: work in progress");
}
}  // namespace mrolr::apps
