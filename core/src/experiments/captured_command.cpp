#include "experiments/captured_command.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "coupling/process_spawn.hpp"

namespace swarmnet {

namespace {

class Pipe {
 public:
  Pipe() {
    if (::pipe2(fds_.data(), O_CLOEXEC) != 0) fds_ = {-1, -1};
  }
  ~Pipe() {
    close_read();
    close_write();
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  [[nodiscard]] bool ok() const { return fds_[0] >= 0; }
  [[nodiscard]] int read_end() const { return fds_[0]; }
  [[nodiscard]] int write_end() const { return fds_[1]; }
  void close_read() { close_end(0); }
  void close_write() { close_end(1); }

 private:
  void close_end(std::size_t i) {
    if (fds_[i] >= 0) ::close(fds_[i]);
    fds_[i] = -1;
  }
  std::array<int, 2> fds_{};
};

}  // namespace

CapturedCommand run_captured(const std::vector<std::string>& arguments) {
  CapturedCommand result;
  if (arguments.empty()) {
    result.error = "no command";
    return result;
  }
  Pipe out;
  Pipe err;
  if (!out.ok() || !err.ok()) {
    result.error = std::string("cannot create a pipe: ") + std::strerror(errno);
    return result;
  }
  SpawnRequest request;
  request.executable = arguments.front();
  request.arguments = arguments;
  request.output_fd = out.write_end();
  request.error_fd = err.write_end();
  request.search_path = true;
  std::string error;
  const pid_t pid = spawn_process(request, error);
  out.close_write();
  err.close_write();
  if (pid < 0) {
    result.error = error;
    return result;
  }
  result.started = true;

  std::array<pollfd, 2> fds = {pollfd{out.read_end(), POLLIN, 0},
                               pollfd{err.read_end(), POLLIN, 0}};
  std::array<std::string*, 2> sinks = {&result.output, &result.errors};
  std::array<char, 4096> buffer{};
  int open = 2;
  while (open > 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
      if (n > 0) {
        sinks[i]->append(buffer.data(), static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        fds[i].fd = -1;  // end of file (or an error): stop watching it
        --open;
      }
    }
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status)     ? WEXITSTATUS(status)
                     : WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                           : -1;
  return result;
}

std::string describe_failure(const std::vector<std::string>& arguments,
                             const CapturedCommand& result) {
  const std::string name = arguments.empty() ? std::string("(none)") : arguments.front();
  if (!result.started) return "cannot run " + name + ": " + result.error;
  std::string text = name + ": exit " + std::to_string(result.exit_code);
  std::string last;
  std::size_t begin = 0;
  while (begin < result.errors.size()) {
    std::size_t end = result.errors.find('\n', begin);
    if (end == std::string::npos) end = result.errors.size();
    if (end > begin) last = result.errors.substr(begin, end - begin);
    begin = end + 1;
  }
  if (!last.empty()) text += ": " + last;
  return text;
}

}  // namespace swarmnet
