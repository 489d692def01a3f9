#include "plot_interpreter.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <sstream>

#include "coupling/process_spawn.hpp"

namespace swarmnet {

namespace {

// Whether `python -c "import matplotlib"` succeeds, its output discarded.
bool imports_matplotlib(const std::filesystem::path& python) {
  std::string error;
  const pid_t pid =
      spawn_process({python, {python.string(), "-c", "import matplotlib"}, {}, "/dev/null"}, error);
  if (pid < 0) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return false;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

PlotInterpreter find_plot_interpreter(const std::filesystem::path& preferred,
                                      const std::string& path_list) {
  std::vector<std::filesystem::path> candidates{preferred};
  std::stringstream dirs(path_list);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (!dir.empty()) candidates.push_back(std::filesystem::path(dir) / "python3");
  }
  PlotInterpreter search;
  for (const auto& candidate : candidates) {
    if (std::find(search.tried.begin(), search.tried.end(), candidate) != search.tried.end() ||
        access(candidate.c_str(), X_OK) != 0) {
      continue;
    }
    search.tried.push_back(candidate);
    if (imports_matplotlib(candidate)) {
      search.python = candidate;
      break;
    }
  }
  return search;
}

std::string no_plot_interpreter_message(const PlotInterpreter& search) {
  std::string message = "no python3 that imports matplotlib";
  if (search.tried.empty()) {
    message += " (no python3 found at /usr/bin/python3 or on PATH)";
  } else {
    message += "; tried:";
    for (const auto& python : search.tried) message += "\n  " + python.string();
  }
  return message +
         "\ninstall Debian's python3 and python3-matplotlib (apt-get install python3 "
         "python3-matplotlib; ./swarmnet plot does), or matplotlib for one of the above";
}

}  // namespace swarmnet
