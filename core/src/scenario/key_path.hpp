// The dotted path of a scenario key, as written in error messages and in --set overrides:
// "robots.controllers.1.params.rate_hz" (list elements are numbered from 0).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace swarmnet {

class KeyPath {
 public:
  KeyPath() = default;
  explicit KeyPath(std::vector<std::string> parts) : parts_(std::move(parts)) {}

  // "a.b.c" split at every dot; empty parts are kept (a caller that refuses them can see them).
  [[nodiscard]] static KeyPath parse(std::string_view dotted) {
    KeyPath path;
    for (std::size_t start = 0;;) {
      const std::size_t dot = dotted.find('.', start);
      path.parts_.emplace_back(dotted.substr(start, dot - start));
      if (dot == std::string_view::npos) return path;
      start = dot + 1;
    }
  }

  [[nodiscard]] KeyPath operator/(std::string_view key) const {
    KeyPath child = *this;
    child.parts_.emplace_back(key);
    return child;
  }
  [[nodiscard]] KeyPath operator/(std::size_t index) const { return *this / std::to_string(index); }

  [[nodiscard]] const std::vector<std::string>& parts() const { return parts_; }
  [[nodiscard]] bool empty() const { return parts_.empty(); }

  // True when `prefix` is this path or one of its ancestors.
  [[nodiscard]] bool starts_with(const KeyPath& prefix) const {
    if (prefix.parts_.size() > parts_.size()) return false;
    for (std::size_t i = 0; i < prefix.parts_.size(); ++i) {
      if (prefix.parts_[i] != parts_[i]) return false;
    }
    return true;
  }

  // "a.b.c"; the scenario's top level, which has no key, reads "(top level)".
  [[nodiscard]] std::string text() const {
    if (parts_.empty()) return "(top level)";
    std::string joined;
    for (const auto& part : parts_) {
      if (!joined.empty()) joined += '.';
      joined += part;
    }
    return joined;
  }

  friend bool operator==(const KeyPath&, const KeyPath&) = default;

 private:
  std::vector<std::string> parts_;
};

}  // namespace swarmnet
