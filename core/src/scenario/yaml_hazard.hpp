// Inputs that make Debian's yaml-cpp (0.7) loop forever while allocating, found by fuzzing: a ','
// where a node begins outside [ ] and { } (",a: 1", "--- ,a", a comment and then "  ,x"), also
// after a tag or an anchor (" ! ,a", " &x ,a", "- ! ,a") or inside one (" !,a"), or after a
// quoted scalar, a flow collection or an alias ("\"a\" ,b", "[1] ,b", "*a ,b"). They are
// refused before yaml-cpp sees them, as the syntax errors they are: in YAML a plain scalar cannot
// begin with ',', nor may a tag or an anchor hold one. (The one valid text refused with them: a
// plain scalar continued on a line that begins with ','; quote such a value.)
#pragma once

#include <optional>
#include <string_view>

namespace swarmnet {

struct TextPosition {
  int line = 0;                   // 0-based, as YAML::Mark
  int column = 0;                 // 0-based
  const char* problem = nullptr;  // what is wrong there, for the syntax error
};

// What is wrong with such a text, for the syntax error that refuses it.
inline constexpr const char* kYamlHazardProblem =
    "',' cannot begin a value outside [ ] or { }, nor stand in a tag or an anchor";

// A NUL byte anywhere: YAML allows none (it is not a printable character), and yaml-cpp, which
// stops reading at one, then loops forever on a ',' after it (found by fuzzing: "\0,\0` \0a[w").
inline constexpr const char* kYamlNulProblem =
    "the text holds a NUL byte, which YAML does not allow (is this a binary file?)";

// Where `text` holds such a hazard or a NUL byte, if it does, with the problem to report
// (kYamlHazardProblem or kYamlNulProblem).
std::optional<TextPosition> find_yaml_hazard(std::string_view text);

}  // namespace swarmnet
