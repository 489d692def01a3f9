// A value echoed in a message, cut to a readable length: a 100 KB value quoted whole would bury
// the message (and a terminal). Longer text keeps its first 80 characters and says its length.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace swarmnet {

inline constexpr std::size_t kShownValueChars = 80;

// `text` itself when it has at most kShownValueChars characters; else its first
// kShownValueChars + "... (N bytes)".
std::string shown_value(std::string_view text);

}  // namespace swarmnet
