#include "scenario/scenario_overrides.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

#include "scenario/key_path.hpp"
#include "scenario/shown_value.hpp"

namespace swarmnet {

namespace {

std::optional<std::size_t> parse_index(const std::string& text) {
  if (text.empty() ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  std::size_t index = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), index);
  if (result.ec != std::errc()) return std::nullopt;
  return index;
}

std::string index_range(std::size_t size) {
  return size == 0 ? std::string("no index: the list is empty")
                   : "an index 0.." + std::to_string(size - 1);
}

// Applies one override; returns the problem ("what; expected FORM") and the path it concerns,
// or nothing when it applied.
struct OverrideProblem {
  KeyPath path;
  std::string what;
  std::string expected;
};

std::optional<OverrideProblem> apply_one(YAML::Node& root, const std::vector<std::string>& parts,
                                         const YAML::Node& value) {
  YAML::Node current;
  current.reset(root);  // reset() rebinds; operator= would overwrite the node in the tree
  KeyPath path;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    const KeyPath here = path / part;
    YAML::Node next;
    if (current.IsSequence()) {
      const auto index = parse_index(part);
      if (!index) {
        return OverrideProblem{here,
                               "'" + part + "' is not an index, and " + path.text() + " is a list",
                               index_range(current.size())};
      }
      if (*index >= current.size()) {
        return OverrideProblem{here,
                               "index " + part + " is out of range: the list has " +
                                   std::to_string(current.size()) +
                                   (current.size() == 1 ? " element" : " elements"),
                               index_range(current.size())};
      }
      if (last) {
        current[*index] = value;
        return std::nullopt;
      }
      next.reset(current[*index]);
    } else if (current.IsMap() || current.IsNull()) {
      if (last) {
        current[part] = value;  // a null node becomes a mapping
        return std::nullopt;
      }
      if (!current[part] || current[part].IsNull()) current[part] = YAML::Node(YAML::NodeType::Map);
      next.reset(current[part]);
    } else {
      return OverrideProblem{path,
                             "is a scalar (" + shown_value(current.Scalar()) +
                                 "), so it has no key or index '" + shown_value(part) + "'",
                             "a path through mappings and lists"};
    }
    current.reset(next);
    path = here;
  }
  return std::nullopt;
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     ProblemList& problems) {
  const std::string form = "KEY.PATH=VALUE, e.g. robots.count=100";
  for (const auto& text : overrides) {
    const std::size_t equals = text.find('=');
    const std::string key = text.substr(0, equals);
    const std::string origin = "--set " + shown_value(key.empty() ? text : key);
    // "ORIGIN: [PATH: ]WHAT; expected FORM"
    const auto report = [&](const std::string& path, const std::string& what,
                            const std::string& expected) {
      std::string line = origin;
      line.append(": ").append(path).append(path.empty() ? "" : ": ").append(what);
      line.append("; expected ").append(expected);
      problems.add_line(std::move(line));
    };
    std::string quoted = "'";
    quoted.append(shown_value(text)).append("'");
    if (equals == std::string::npos) {
      report("", quoted + " has no '='", form);
      continue;
    }
    const std::vector<std::string> parts = KeyPath::parse(key).parts();
    if (key.empty() ||
        std::any_of(parts.begin(), parts.end(), [](const auto& p) { return p.empty(); })) {
      report("", quoted + " has an empty key path or component", form);
      continue;
    }
    const std::string value_text = text.substr(equals + 1);
    YAML::Node value;
    try {
      value = YAML::Load(value_text);
    } catch (const YAML::Exception& error) {
      std::string what = "value '";
      what.append(value_text).append("' is not valid YAML (").append(error.msg).append(")");
      report(KeyPath(parts).text(), what, "a scalar, a flow list [a, b] or a flow mapping {k: v}");
      continue;
    }
    if (const auto problem = apply_one(root, parts, value)) {
      report(problem->path.text(), problem->what, problem->expected);
      continue;
    }
    problems.mark_overridden(KeyPath(parts), origin);
  }
}

}  // namespace swarmnet
