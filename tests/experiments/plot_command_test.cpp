// `swarmnet plot`: the figure script run with a python3 that has matplotlib, even where the
// first python3 on PATH has none (pyenv, a virtualenv), and a clear error where none has it.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <fstream>
#include <optional>

#include "command_runner.hpp"
#include "plot_interpreter.hpp"

namespace swarmnet::testing {
namespace {

namespace fs = std::filesystem;

// A python3 that lacks matplotlib, as the first python3 on PATH often does.
fs::path write_python_without_matplotlib(const TempDir& dir) {
  fs::create_directories(dir.path() / "bin");
  const fs::path python = dir.path() / "bin" / "python3";
  std::ofstream(python) << "#!/bin/sh\n"
                        << "echo \"ModuleNotFoundError: No module named 'matplotlib'\" >&2\n"
                        << "exit 1\n";
  chmod(python.c_str(), 0755);
  return python;
}

bool debian_python_has_matplotlib() {
  return find_plot_interpreter("/usr/bin/python3", "").python == "/usr/bin/python3";
}

TEST(PlotInterpreter, SkipsAPython3WithoutMatplotlibForOneWithIt) {
  if (!debian_python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  TempDir dir;
  const fs::path lacking = write_python_without_matplotlib(dir);
  const PlotInterpreter search =
      find_plot_interpreter(lacking, lacking.parent_path().string() + ":/usr/bin");
  EXPECT_EQ(search.python, fs::path("/usr/bin/python3"));
  EXPECT_EQ(search.tried, (std::vector<fs::path>{lacking, "/usr/bin/python3"}))
      << "each candidate once, in order";
}

TEST(PlotInterpreter, NoneWithMatplotlibNamesWhatWasTriedAndWhatToInstall) {
  TempDir dir;
  const fs::path lacking = write_python_without_matplotlib(dir);
  const PlotInterpreter search = find_plot_interpreter(
      dir.path() / "no" / "python3", "/nonexistent:" + lacking.parent_path().string());
  EXPECT_TRUE(search.python.empty());
  const std::string message = no_plot_interpreter_message(search);
  EXPECT_NE(message.find(lacking.string()), std::string::npos) << message;
  EXPECT_NE(message.find("python3-matplotlib"), std::string::npos) << message;
}

// Sets PATH for one test, restoring it after.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& value) {
    if (const char* old = std::getenv("PATH")) old_ = old;
    setenv("PATH", value.c_str(), 1);
  }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;
  ~ScopedPath() {
    if (old_) setenv("PATH", old_->c_str(), 1);
  }

 private:
  std::optional<std::string> old_;
};

TEST(PlotCommand, WritesAFigureThoughTheFirstPython3OnPathLacksMatplotlib) {
  if (!debian_python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  TempDir dir;
  const fs::path lacking = write_python_without_matplotlib(dir);
  const fs::path results = dir.path() / "results.csv";
  {
    std::ofstream csv(results);
    csv << "run_id,seed,status,robots.count,network.routing,pdr\n";
    for (int n : {10, 20}) {
      for (const char* routing : {"aodv", "flooding"}) {
        for (int seed : {1, 2}) csv << "r," << seed << ",ok," << n << ',' << routing << ",0.8\n";
      }
    }
  }
  const fs::path figure = dir.path() / "fig.png";
  ScopedPath path(lacking.parent_path().string() + ":" + std::getenv("PATH"));
  const auto result =
      run_swarmnet("plot " + results.string() +
                   " --x robots.count --y pdr --by network.routing --out " + figure.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream png(figure, std::ios::binary);
  std::string magic(8, '\0');
  png.read(magic.data(), 8);
  EXPECT_EQ(magic, std::string("\x89PNG\r\n\x1a\n", 8)) << result.output;

  // The script's own errors and help come through unchanged.
  const auto bad =
      run_swarmnet("plot " + results.string() + " --x robots --y pdr --out " + figure.string());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("no column 'robots'"), std::string::npos) << bad.output;
  EXPECT_NE(run_swarmnet("plot --help").output.find("--logx"), std::string::npos);
}

}  // namespace
}  // namespace swarmnet::testing
