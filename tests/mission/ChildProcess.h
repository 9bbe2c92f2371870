#pragma once
// A program of build/bin run as a child process, its standard output read line by line, a
// signal sent and its exit awaited (with a deadline, so a test never hangs).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace mrolr::test
{
class ChildProcess
{
 public:
	explicit ChildProcess(const std::vector<std::string>& argv)
	{
		int fds[2];
		if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
		posix_spawn_file_actions_t actions;
		posix_spawn_file_actions_init(&actions);
		posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
		posix_spawn_file_actions_addclose(&actions, fds[0]);
		std::vector<char*> args;
		for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
		args.push_back(nullptr);
		const int rc = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
		posix_spawn_file_actions_destroy(&actions);
		close(fds[1]);
		out_ = fds[0];
		if (rc != 0) throw std::runtime_error("cannot start " + argv[0]);
	}
	~ChildProcess()
	{
		if (pid_ > 0 && !exited_)
		{
			kill(pid_, SIGKILL);
			waitpid(pid_, nullptr, 0);
		}
		close(out_);
	}
	/** The next line of its standard output, or "" after @p timeout_s or at its end. */
	std::string readLine(double timeout_s)
	{
		const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
		while (std::chrono::steady_clock::now() < end)
		{
			if (const auto nl = buffer_.find('\n'); nl != std::string::npos)
			{
				const std::string line = buffer_.substr(0, nl);
				buffer_.erase(0, nl + 1);
				return line;
			}
			pollfd p{out_, POLLIN, 0};
			if (poll(&p, 1, 50) <= 0) continue;
			char chunk[512];
			const ssize_t n = read(out_, chunk, sizeof chunk);
			if (n <= 0) return "";
			buffer_.append(chunk, static_cast<size_t>(n));
		}
		return "";
	}
	void signal(int sig) { kill(pid_, sig); }
	/** Its exit code (128 + signal when a signal ended it); -1 when it did not end in time. */
	int wait(double timeout_s)
	{
		const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
		while (std::chrono::steady_clock::now() < end)
		{
			int status = 0;
			if (waitpid(pid_, &status, WNOHANG) == pid_)
			{
				exited_ = true;
				return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
			}
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
		}
		return -1;
	}

 private:
	pid_t pid_ = -1;
	int out_ = -1;
	bool exited_ = false;
	std::string buffer_;
};

}  // namespace mrolr::test
