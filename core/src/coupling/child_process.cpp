#include "coupling/child_process.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>

#include "coupling/process_spawn.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet {

ChildProcess::ChildProcess(const std::vector<std::string>& arguments,
                           const std::vector<std::string>& environment) {
  SpawnRequest request;
  request.executable = "/proc/self/exe";
  request.arguments = {"swarmnet"};
  request.arguments.insert(request.arguments.end(), arguments.begin(), arguments.end());
  request.extra_environment = environment;
  std::string error;
  pid_ = spawn_process(request, error);
  if (pid_ < 0) throw RunError("cannot start the network half: " + error);
}

ChildProcess::~ChildProcess() {
  if (!reaped_ && pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status_, 0);
  }
}

bool ChildProcess::alive() {
  if (reaped_) return false;
  const pid_t r = ::waitpid(pid_, &status_, WNOHANG);
  if (r == pid_) reaped_ = true;
  return !reaped_;
}

std::string ChildProcess::wait(std::chrono::milliseconds grace) {
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (alive() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (alive()) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status_, 0);
    reaped_ = true;
    return "did not stop within " + std::to_string(grace.count()) + " ms and was killed";
  }
  return describe_status();
}

std::string ChildProcess::describe_status() const {
  if (WIFEXITED(status_)) {
    return WEXITSTATUS(status_) == 0 ? ""
                                     : "exited with status " + std::to_string(WEXITSTATUS(status_));
  }
  if (WIFSIGNALED(status_)) {
    const int signal = WTERMSIG(status_);
    return "was killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
  }
  return "ended with wait status " + std::to_string(status_);
}

}  // namespace swarmnet
