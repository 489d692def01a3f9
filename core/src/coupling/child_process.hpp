// A `swarmnet net` child process: started with posix_spawn from this very executable, watched
// without blocking, and never left running behind the parent.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace swarmnet {

class ChildProcess {
 public:
  // Runs this executable (/proc/self/exe) with `arguments`, its environment this process's plus
  // `environment` ("NAME=value" entries; a secret handed over there is readable by this user
  // only, unlike the arguments). Throws RunError.
  explicit ChildProcess(const std::vector<std::string>& arguments,
                        const std::vector<std::string>& environment = {});
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ChildProcess(ChildProcess&&) = delete;
  ChildProcess& operator=(ChildProcess&&) = delete;
  ~ChildProcess();  // kills and reaps the child if it still runs

  [[nodiscard]] pid_t pid() const { return pid_; }
  // Non-blocking: false once the child has exited (its status is then kept).
  bool alive();
  // Waits up to `grace` for the child to exit, then kills it. Returns "" for a clean exit
  // (status 0), else how it ended ("exited with status 3", "was killed by signal 9 (Killed)").
  std::string wait(std::chrono::milliseconds grace);

 private:
  std::string describe_status() const;

  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

}  // namespace swarmnet
