#include "scenario/problem_list.hpp"

#include "scenario/shown_value.hpp"

namespace swarmnet {

void ProblemList::mark_overridden(KeyPath path, std::string origin) {
  overrides_.push_back({std::move(path), std::move(origin)});
}

bool ProblemList::overridden(const KeyPath& path) const {
  for (const auto& entry : overrides_) {
    if (path.starts_with(entry.path)) return true;
  }
  return false;
}

std::string ProblemList::locate(const KeyPath& path, const YAML::Mark& mark) const {
  // The most specific override covering `path` wins; later overrides win over earlier ones.
  const Override* covering = nullptr;
  for (const auto& entry : overrides_) {
    if (path.starts_with(entry.path) &&
        (covering == nullptr || entry.path.parts().size() >= covering->path.parts().size())) {
      covering = &entry;
    }
  }
  if (covering != nullptr) return covering->origin;
  if (!mark.is_null() && mark.line >= 0) {
    return file_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
  }
  // A node an override created on the way to its value (a missing mapping) has no mark.
  for (const auto& entry : overrides_) {
    if (entry.path.starts_with(path)) return entry.origin;
  }
  // Nothing in the file to point at (an empty or comment-only file, a key it lacks entirely):
  // its first line, so that every refusal names a file and a line.
  return file_ + ":1:1";
}

void ProblemList::add(const KeyPath& path, const YAML::Mark& mark, const std::string& what,
                      const std::string& expected) {
  std::string line = locate(path, mark) + ": " + shown_value(path.text()) + ": " + what;
  if (!expected.empty()) line += "; expected " + expected;
  lines_.push_back(std::move(line));
}

}  // namespace swarmnet
