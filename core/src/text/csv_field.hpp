// A name as one CSV field (RFC 4180): as it is, or quoted with its quotes doubled when it holds a
// comma, a quote or a line break, so any name a plugin chose reads back whole.
#pragma once

#include <ostream>
#include <string_view>

namespace swarmnet {

inline void write_csv_field(std::ostream& out, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    out << text;
    return;
  }
  out << '"';
  for (const char c : text) {
    if (c == '"') out << '"';
    out << c;
  }
  out << '"';
}

}  // namespace swarmnet
