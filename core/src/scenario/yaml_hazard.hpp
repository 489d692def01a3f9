// Inputs that make Debian's yaml-cpp (0.7) loop forever while allocating, found by fuzzing: a
// document whose first token is ',' (",a: 1", "--- ,a", a comment and then "  ,x"). They are
// refused before yaml-cpp sees them, as the syntax errors they are.
#pragma once

#include <optional>
#include <string_view>

namespace swarmnet {

struct TextPosition {
  int line = 0;    // 0-based, as YAML::Mark
  int column = 0;  // 0-based
};

// Where `text` holds such a hazard, if it does.
std::optional<TextPosition> find_yaml_hazard(std::string_view text);

}  // namespace swarmnet
