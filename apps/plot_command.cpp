#include "plot_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "plot_interpreter.hpp"
#include "plugin/executable_layout.hpp"
#include "session/exit_codes.hpp"

namespace swarmnet {

namespace {

int refuse(const std::string& message) {
  std::fprintf(stderr, "swarmnet plot: error: %s\n", message.c_str());
  return kExitBadInput;
}

}  // namespace

int plot_command(const std::vector<std::string>& arguments) {
  const std::filesystem::path script = executable_layout().data_dir / "scripts" / "plot.py";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec))
    return refuse("the figure script " + script.string() + " is missing from this installation");
  const char* path = std::getenv("PATH");
  const PlotInterpreter search = find_plot_interpreter("/usr/bin/python3", path ? path : "");
  if (search.python.empty()) return refuse(no_plot_interpreter_message(search));

  std::vector<std::string> words{search.python.string(), script.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(argv[0], argv.data());
  return refuse("cannot start " + search.python.string() + ": " + std::strerror(errno));
}

}  // namespace swarmnet
