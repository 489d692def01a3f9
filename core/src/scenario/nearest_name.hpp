// "Did you mean ...?": the known name closest to a misspelt one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swarmnet {

// Edit distance counting insertions, deletions, substitutions and swaps of adjacent characters
// (optimal string alignment), ignoring ASCII case.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, when it is close enough to be a likely typo: at most
// max(1, length / 3) edits, and fewer edits than either name has characters; ties go to the
// earlier candidate. Failing that, the one candidate that `word` (3 characters or more) begins.
// Otherwise none: callers then list every declared name ("expected one of ...").
std::optional<std::string> nearest_name(std::string_view word,
                                        const std::vector<std::string>& candidates);

}  // namespace swarmnet
