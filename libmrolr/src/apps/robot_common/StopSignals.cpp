// SIGINT / SIGTERM turned into a stop request.
#include <mrolr/apps/StopSignals.h>

#include <csignal>

namespace mrolr::apps
{
namespace
{
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
struct sigaction g_old_int, g_old_term;

void onSignal(int sig)
{
	int none = 0;
	g_signal.compare_exchange_strong(none, sig);
	g_stop = true;
}
}  // namespace

StopSignals::StopSignals()
{
	g_stop = false, g_signal = 0;
	struct sigaction sa{};
	sa.sa_handler = onSignal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, &g_old_int);
	sigaction(SIGTERM, &sa, &g_old_term);
}

StopSignals::~StopSignals()
{
	sigaction(SIGINT, &g_old_int, nullptr);
	sigaction(SIGTERM, &g_old_term, nullptr);
}

std::atomic<bool>& StopSignals::flag()
{
	return g_stop;
}

int StopSignals::received() const
{
	return g_signal;
}

}  // namespace mrolr::apps
