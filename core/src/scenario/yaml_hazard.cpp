#include "scenario/yaml_hazard.hpp"

namespace swarmnet {

std::optional<TextPosition> find_yaml_hazard(std::string_view text) {
  bool document_start = true;  // no token of the current document seen yet
  int line = 0;
  for (std::size_t begin = 0; begin <= text.size(); ++line) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = text.substr(begin, end - begin);
    std::size_t at = row.find_first_not_of(" \t\r");
    if (row.starts_with("---") || row.starts_with("...")) {
      document_start = true;  // a new document: its first token is checked again
      at = row.find_first_not_of(" \t\r", 3);
    }
    if (document_start && at != std::string_view::npos && row[at] != '#' && row[at] != '%') {
      if (row[at] == ',') return TextPosition{line, static_cast<int>(at)};
      document_start = false;
    }
    begin = end + 1;
  }
  return std::nullopt;
}

}  // namespace swarmnet
