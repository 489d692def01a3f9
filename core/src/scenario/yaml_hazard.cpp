#include "scenario/yaml_hazard.hpp"

#include <algorithm>

namespace swarmnet {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Whether row[at] is an indicator that a blank (or the line's end) must follow: "- ", "? ", ": ".
bool is_indicator(std::string_view row, std::size_t at) {
  const char c = row[at];
  return (c == '-' || c == '?' || c == ':') && (at + 1 == row.size() || is_blank(row[at + 1]));
}

// Scans YAML just far enough to know, at each character outside comments and quoted scalars,
// whether a node may begin there and whether it is inside a flow collection ([ ], { }).
class HazardScanner {
 public:
  std::optional<TextPosition> scan(std::string_view text) {
    int line = 0;
    for (std::size_t begin = 0; begin <= text.size(); ++line) {
      std::size_t end = text.find('\n', begin);
      if (end == std::string_view::npos) end = text.size();
      if (auto hazard = scan_row(text.substr(begin, end - begin), line)) return hazard;
      begin = end + 1;
    }
    return std::nullopt;
  }

 private:
  std::optional<TextPosition> scan_row(std::string_view row, int line) {
    const std::size_t first = row.find_first_not_of(" \t\r");
    const auto indent = static_cast<int>(first == std::string_view::npos ? row.size() : first);
    if (block_scalar_indent_ >= 0) {  // a | or > scalar's text: lines more indented, or blank
      if (first == std::string_view::npos || indent > block_scalar_indent_) return std::nullopt;
      block_scalar_indent_ = -1;
    }
    if (quote_ == 0 && flow_depth_ == 0) node_may_begin_ = true;  // a block line's first token
    for (std::size_t at = 0; at < row.size(); ++at) {
      const char c = row[at];
      if (quote_ != 0) {
        if (quote_ == '"' && c == '\\') {
          ++at;
        } else if (c == quote_ && quote_ == '\'' && at + 1 < row.size() && row[at + 1] == '\'') {
          ++at;  // '' inside a single-quoted scalar
        } else if (c == quote_) {
          quote_ = 0;
          // After a quoted scalar only ':' or a comment may follow in block context, so a ','
          // there is the hazard too.
          if (flow_depth_ == 0) node_may_begin_ = true;
        }
        continue;
      }
      if (is_blank(c)) continue;
      if (c == '#' && (at == 0 || is_blank(row[at - 1]))) return std::nullopt;  // a comment
      if (at == 0 && (row.starts_with("---") || row.starts_with("..."))) {
        at += 2;  // a document marker: the next token may be a node
        node_may_begin_ = true;
        continue;
      }
      if (node_may_begin_) {
        if (c == ',' && flow_depth_ == 0)
          return TextPosition{line, static_cast<int>(at), kYamlHazardProblem};
        if (c == '!' || c == '&' || c == '*') {  // a tag, an anchor (the node follows) or an alias
          for (; at + 1 < row.size() && !is_blank(row[at + 1]); ++at) {
            if (row[at + 1] == ',' && flow_depth_ == 0) {
              return TextPosition{line, static_cast<int>(at + 1), kYamlHazardProblem};
            }
          }
          continue;
        }
        if (is_indicator(row, at)) continue;
        if (flow_depth_ == 0 && (c == '|' || c == '>')) {
          block_scalar_indent_ = indent;  // its text follows on the next lines
          for (++at; at < row.size() && row[at] != '#'; ++at) {
            if (row[at] == ',') return TextPosition{line, static_cast<int>(at), kYamlHazardProblem};
          }
          return std::nullopt;
        }
        if (flow_depth_ == 0 && at == 0 && c == '%') return std::nullopt;  // a directive
        node_may_begin_ = false;
        if (c == '"' || c == '\'') {
          quote_ = c;
          continue;
        }
      }
      if (c == '[' || c == '{') {
        ++flow_depth_;
        node_may_begin_ = true;
      } else if ((c == ']' || c == '}') && flow_depth_ > 0) {
        // Back in block context after a flow collection, only ':' or a comment may follow.
        if (--flow_depth_ == 0) node_may_begin_ = true;
      } else if (c == ',' && flow_depth_ > 0) {
        node_may_begin_ = true;
      } else if (c == ':' && (at + 1 == row.size() || is_blank(row[at + 1]) || flow_depth_ > 0)) {
        node_may_begin_ = true;  // a key's value follows
      }
    }
    return std::nullopt;
  }

  int flow_depth_ = 0;
  char quote_ = 0;                // inside a quoted scalar: its quote
  int block_scalar_indent_ = -1;  // inside a | or > scalar: its header line's indentation
  bool node_may_begin_ = true;
};

}  // namespace

std::optional<TextPosition> find_yaml_hazard(std::string_view text) {
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const std::string_view before = text.substr(0, nul);
    const std::size_t line_start = before.rfind('\n');
    const auto line = static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const auto column =
        static_cast<int>(line_start == std::string_view::npos ? nul : nul - line_start - 1);
    return TextPosition{line, column, kYamlNulProblem};
  }
  return HazardScanner().scan(text);
}

}  // namespace swarmnet
