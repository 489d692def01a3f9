// A value echoed in a message, cut to a readable length: a 100 KB value quoted whole would bury
// the message (and a terminal). Longer text keeps its first 80 characters and says its length.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace swarmnet {

inline constexpr std::size_t kShownValueChars = 80;
// A path is shown whole up to the longest the system accepts (PATH_MAX): real paths are often
// longer than 80 characters, and cutting them would hide where.
inline constexpr std::size_t kShownPathChars = 4096;

// `text` itself when it has at most `limit` characters; else its first `limit` characters (not
// cutting a UTF-8 character) + "... (N bytes)".
std::string shown_value(std::string_view text, std::size_t limit = kShownValueChars);

}  // namespace swarmnet
