// Reals in output files: the shortest decimal that reads back as the same double, so a file's
// bytes depend only on the values (not on a stream's precision setting) and nothing is rounded.
#pragma once

#include <array>
#include <charconv>
#include <ostream>

namespace swarmnet {

inline void write_shortest(std::ostream& out, double value) {
  std::array<char, 32> text{};
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  out.write(text.data(), result.ptr - text.data());
}

}  // namespace swarmnet
