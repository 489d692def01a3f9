// Every problem found in a scenario, each formatted as one line:
//
//   FILE:LINE:COLUMN: KEY.PATH: what is wrong; expected FORM
//
// LINE and COLUMN are 1-based. A value that came from the command line is located by the option
// that set it ("--set robots.count", "--seed") instead of a place in the file.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scenario/key_path.hpp"

namespace swarmnet {

class ProblemList {
 public:
  explicit ProblemList(std::string file) : file_(std::move(file)) {}

  // Values at `path` and below were set by the command-line option `origin`.
  void mark_overridden(KeyPath path, std::string origin);

  // True when a command-line option set the value at `path` (or a mapping holding it).
  [[nodiscard]] bool overridden(const KeyPath& path) const;

  // Where the value at `path` (whose YAML mark is `mark`) came from.
  [[nodiscard]] std::string locate(const KeyPath& path, const YAML::Mark& mark) const;

  // Adds "LOCATION: PATH: what; expected FORM" (without "; expected" when `expected` is empty).
  void add(const KeyPath& path, const YAML::Mark& mark, const std::string& what,
           const std::string& expected);
  // Adds a line formatted by the caller.
  void add_line(std::string line) { lines_.push_back(std::move(line)); }

  [[nodiscard]] bool empty() const { return lines_.empty(); }
  [[nodiscard]] std::size_t size() const { return lines_.size(); }
  [[nodiscard]] const std::vector<std::string>& lines() const { return lines_; }
  [[nodiscard]] const std::string& file() const { return file_; }

 private:
  struct Override {
    KeyPath path;
    std::string origin;
  };
  std::string file_;
  std::vector<Override> overrides_;
  std::vector<std::string> lines_;
};

}  // namespace swarmnet
