#include "experiments/sweep_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "scenario/key_path.hpp"
#include "scenario/problem_list.hpp"
#include "scenario/yaml_hazard.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

// A sweep file's problems are reported as a scenario's are (scenario/problem_list.hpp).
void add_problem(ProblemList& problems, const YAML::Node& node, const std::string& key,
                 const std::string& what, const std::string& expected = "") {
  problems.add(KeyPath::parse(key), node.Mark(), what, expected);
}

std::string locate(const ProblemList& problems, const YAML::Node& node) {
  return problems.locate(KeyPath{}, node.Mark());
}

std::string flow_text(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

// A readable, file-name-safe form of a value: its text with anything but [A-Za-z0-9.+-] as '_';
// a mapping with a plugin key goes by the plugin's name; anything long by its position.
std::string id_part(const YAML::Node& node, std::size_t index) {
  std::string text;
  if (node.IsScalar()) {
    text = node.Scalar();
  } else if (node.IsMap() && node["plugin"] && node["plugin"].IsScalar()) {
    text = node["plugin"].Scalar();
  }
  for (char& c : text) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '+' || c == '-';
    if (!safe) c = '_';
  }
  if (text.empty() || text.size() > 32 || text == "." || text == "..") {
    text = "v" + std::to_string(index + 1);
  }
  return text;
}

bool valid_key(const std::string& key) {
  if (key.empty()) return false;
  return std::ranges::none_of(KeyPath::parse(key).parts(),
                              [](const std::string& p) { return p.empty(); });
}

// The short name of a key: its last component, or the one before when that is "plugin" (so that
// network.routing.plugin reads "routing").
std::string short_name(const std::string& key) {
  const auto parts = KeyPath::parse(key).parts();
  if (parts.size() >= 2 && parts.back() == "plugin") return parts[parts.size() - 2];
  return parts.back();
}

std::uint64_t read_seed(const YAML::Node& node, ProblemList& problems, const std::string& key,
                        bool& ok) {
  try {
    const auto text = node.IsScalar() ? node.Scalar() : std::string();
    if (!text.empty() && text.front() != '-') return node.as<std::uint64_t>();
  } catch (const YAML::Exception&) {
  }
  add_problem(problems, node, key, "not a seed", "an integer 0..2^64-1");
  ok = false;
  return 0;
}

// A name for a linked axis: a word, so that it cannot be mistaken for a key path.
bool valid_axis_name(const std::string& name) {
  return !name.empty() && std::ranges::all_of(name, [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

// The values of one swept key; empty (with a problem added) unless `values` is a non-empty list.
std::vector<SweepValue> read_values(const YAML::Node& values, const std::string& where,
                                    ProblemList& problems) {
  std::vector<SweepValue> read;
  if (!values.IsSequence() || values.size() == 0) {
    add_problem(problems, values, where, "not a non-empty list", "[value, value, ...]");
    return read;
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    read.push_back({flow_text(values[i]), id_part(values[i], i), locate(problems, values[i])});
  }
  return read;
}

// Run ids are made of the points' id parts, so two points of an axis must not share one.
void check_distinct_ids(const SweepAxis& axis, const YAML::Node& values, const std::string& where,
                        ProblemList& problems) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < axis.points.size(); ++i) {
    if (!seen.insert(axis.points[i].id_part()).second) {
      add_problem(problems, values[i], where,
                  "value " + axis.points[i].values.front().text +
                      " gives the same run id as an earlier one",
                  axis.linked ? "distinct values of the first key, which names the runs"
                              : "distinct values");
    }
  }
}

// `key: [v1, v2, ...]`: one key, one point per value.
std::optional<SweepAxis> read_plain_axis(const YAML::Node& key_node, const YAML::Node& values,
                                         ProblemList& problems) {
  const std::string key = key_node.as<std::string>();
  if (!valid_key(key)) {
    add_problem(problems, key_node, "grid." + key, "not a key path", "a.b.c");
    return std::nullopt;
  }
  auto read = read_values(values, "grid." + key, problems);
  if (read.empty()) return std::nullopt;
  SweepAxis axis;
  axis.name = short_name(key);
  axis.keys = {key};
  for (auto& value : read) axis.points.push_back({{std::move(value)}});
  check_distinct_ids(axis, values, "grid." + key, problems);
  return axis;
}

// `name: {key: [...], key: [...]}`: several keys that vary together. Every list has as many values
// as the first, and the i-th values of all keys make the i-th point.
std::optional<SweepAxis> read_linked_axis(const YAML::Node& name_node, const YAML::Node& keys,
                                          ProblemList& problems) {
  const std::string name = name_node.as<std::string>();
  const std::string where = "grid." + name;
  constexpr const char* kLinkedForm =
      "a linked axis, name: {key path: [values], key path: [values], ...} with a word "
      "(letters, digits, _ or -) as its name";
  if (!valid_axis_name(name)) {
    add_problem(problems, name_node, where, "a mapping here is a linked axis, which needs a name",
                kLinkedForm);
    return std::nullopt;
  }
  if (name == "seed") {
    add_problem(problems, name_node, where, "seed names the seed in run ids", "another name");
    return std::nullopt;
  }
  if (keys.size() == 0) {
    add_problem(problems, keys, where, "an empty linked axis", kLinkedForm);
    return std::nullopt;
  }
  SweepAxis axis;
  axis.name = name;
  axis.linked = true;
  std::vector<std::vector<SweepValue>> columns;
  YAML::Node first_values;
  bool ok = true;
  for (const auto& entry : keys) {
    const std::string key = entry.first.as<std::string>();
    if (!valid_key(key)) {
      add_problem(problems, entry.first, where + "." + key, "not a key path", "a.b.c");
      ok = false;
      continue;
    }
    auto read = read_values(entry.second, where + "." + key, problems);
    if (read.empty()) {
      ok = false;
      continue;
    }
    if (columns.empty()) {
      first_values = entry.second;
    } else if (read.size() != columns.front().size()) {
      add_problem(problems, entry.second, where + "." + key,
                  std::to_string(read.size()) + (read.size() == 1 ? " value" : " values") +
                      " where " + axis.keys.front() + " has " +
                      std::to_string(columns.front().size()),
                  "one value per point: every key of a linked axis has as many values");
      ok = false;
      continue;
    }
    axis.keys.push_back(key);
    columns.push_back(std::move(read));
  }
  if (!ok || columns.empty()) return std::nullopt;
  for (std::size_t i = 0; i < columns.front().size(); ++i) {
    SweepPoint point;
    for (auto& column : columns) point.values.push_back(std::move(column[i]));
    axis.points.push_back(std::move(point));
  }
  check_distinct_ids(axis, first_values, where + "." + axis.keys.front(), problems);
  return axis;
}

// A key may be set once: under set, or on one axis.
void check_each_key_once(const SweepSpec& spec, ProblemList& problems) {
  std::map<std::string, std::string> owner;  // key -> where it was given first
  for (const auto& fixed : spec.fixed) owner.emplace(fixed.key, "set");
  for (const auto& axis : spec.axes) {
    for (std::size_t k = 0; k < axis.keys.size(); ++k) {
      const std::string& key = axis.keys[k];
      const std::string here = axis.linked ? "grid." + axis.name : "grid";
      const auto [it, added] = owner.emplace(key, here);
      if (added) continue;
      // Located at the key's first value: the axis's own node is not kept.
      const std::string what =
          it->second == "set" ? "also given under set" : "also given under " + it->second;
      problems.add_line(axis.points.front().values[k].location + ": " + here + "." + key + ": " +
                        what + "; expected each key once");
    }
  }
}

// Plain axes go by their key's short name unless another axis has it too (or it is "seed", which
// run ids already use); then by the whole key path with '-' for '.'.
void name_axes(std::vector<SweepAxis>& axes, ProblemList& problems) {
  for (auto& axis : axes) {
    if (axis.linked) continue;
    const auto clashes = std::ranges::count_if(axes, [&](const SweepAxis& other) {
      return (other.linked ? other.name : short_name(other.keys.front())) == axis.name;
    });
    if (clashes > 1 || axis.name == "seed") {
      axis.name = axis.keys.front();
      std::ranges::replace(axis.name, '.', '-');
    }
  }
  for (std::size_t a = 0; a < axes.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      if (axes[a].linked && axes[b].linked && axes[a].name == axes[b].name) {
        problems.add_line(axes[a].points.front().values.front().location + ": grid." +
                          axes[a].name +
                          ": a second linked axis of that name; expected "
                          "distinct names");
      }
    }
  }
}

constexpr const char* kForm =
    "keys base (scenario file), out (directory), set (key path: value), grid (key path: list of "
    "values, or name: {key path: list, ...} for keys that vary together), seeds (list of "
    "integers, or {first: N, count: M})";

}  // namespace

SweepError::SweepError(std::vector<std::string> problems)
    : std::runtime_error(join(problems, "\n")), problems_(std::move(problems)) {}

SweepSpec load_sweep(const std::filesystem::path& file) {
  SweepSpec spec;
  spec.file = file;
  const std::string name = file.string();
  ProblemList problems(name);
  YAML::Node root;
  try {
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    if (!in || !std::filesystem::is_regular_file(file, ec)) {
      throw SweepError({name + ": cannot read the file (a sweep file is a regular YAML file)"});
    }
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    if (const auto hazard = find_yaml_hazard(text)) {
      throw SweepError({name + ":" + std::to_string(hazard->line + 1) + ":" +
                        std::to_string(hazard->column + 1) +
                        ": not valid YAML: " + hazard->problem});
    }
    root = YAML::Load(text);
  } catch (const YAML::ParserException& error) {
    throw SweepError({name + ":" + std::to_string(error.mark.line + 1) + ":" +
                      std::to_string(error.mark.column + 1) + ": not valid YAML: " + error.msg});
  }
  if (!root.IsMap()) throw SweepError({name + ": a sweep file is a mapping; expected " + kForm});

  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    if (key != "base" && key != "out" && key != "set" && key != "grid" && key != "seeds") {
      add_problem(problems, entry.first, key, "unknown key", kForm);
    }
  }

  const YAML::Node base = root["base"];
  if (!base) {
    problems.add_line(name +
                      ": base: missing; expected the scenario file to sweep, relative to "
                      "the sweep file");
  } else if (!base.IsScalar() || base.Scalar().empty()) {
    add_problem(problems, base, "base", "not a file name",
                "a scenario file relative to the sweep file");
  } else {
    spec.base = std::filesystem::absolute(file.parent_path() / base.Scalar()).lexically_normal();
    if (!std::filesystem::is_regular_file(spec.base)) {
      add_problem(problems, base, "base", "no such file: " + spec.base.string(),
                  "an existing scenario file");
    }
  }

  if (const YAML::Node out = root["out"]) {
    if (!out.IsScalar() || out.Scalar().empty()) {
      add_problem(problems, out, "out", "not a directory name", "a path");
    } else {
      spec.out = out.Scalar();
    }
  }

  if (const YAML::Node set = root["set"]) {
    if (!set.IsMap()) {
      add_problem(problems, set, "set", "not a mapping", "key path: value, e.g. duration_s: 60");
    } else {
      for (const auto& entry : set) {
        const std::string key = entry.first.as<std::string>();
        if (!valid_key(key)) {
          add_problem(problems, entry.first, "set." + key, "not a key path", "a.b.c");
          continue;
        }
        spec.fixed.push_back({key, flow_text(entry.second), locate(problems, entry.second)});
      }
    }
  }

  const YAML::Node grid = root["grid"];
  if (!grid) {
    problems.add_line(name +
                      ": grid: missing; expected key path: list of values (an empty "
                      "mapping {} runs the base scenario alone)");
  } else if (!grid.IsMap()) {
    add_problem(problems, grid, "grid", "not a mapping",
                "key path: list of values, e.g. robots.count: [25, 50]");
  } else {
    for (const auto& entry : grid) {
      auto axis = entry.second.IsMap() ? read_linked_axis(entry.first, entry.second, problems)
                                       : read_plain_axis(entry.first, entry.second, problems);
      if (axis) spec.axes.push_back(std::move(*axis));
    }
  }
  check_each_key_once(spec, problems);
  name_axes(spec.axes, problems);

  const YAML::Node seeds = root["seeds"];
  bool ok = true;
  if (!seeds) {
    spec.seeds = {1};
  } else if (seeds.IsSequence() && seeds.size() > 0) {
    std::set<std::uint64_t> seen;
    for (const auto& node : seeds) {
      bool valid = true;
      const std::uint64_t seed = read_seed(node, problems, "seeds", valid);
      if (valid && !seen.insert(seed).second) {
        add_problem(problems, node, "seeds", "repeated seed", "distinct seeds");
      }
      spec.seeds.push_back(seed);
    }
  } else if (seeds.IsMap() && seeds["first"] && seeds["count"] && seeds.size() == 2) {
    const std::uint64_t first = read_seed(seeds["first"], problems, "seeds.first", ok);
    const std::uint64_t count = read_seed(seeds["count"], problems, "seeds.count", ok);
    if (ok && (count == 0 || count > 100000)) {
      add_problem(problems, seeds["count"], "seeds.count", "out of range", "1..100000");
    } else if (ok) {
      for (std::uint64_t i = 0; i < count; ++i) spec.seeds.push_back(first + i);
    }
  } else {
    add_problem(problems, seeds, "seeds", "not a list of seeds",
                "[1, 2, 3] or {first: 1, count: 10}");
  }

  if (!problems.lines().empty()) throw SweepError(problems.lines());
  return spec;
}

std::size_t SweepSpec::run_count() const {
  std::size_t count = seeds.size();
  for (const auto& axis : axes) {
    const std::size_t points = axis.points.size();
    if (points != 0 && count > std::numeric_limits<std::size_t>::max() / points) {
      return std::numeric_limits<std::size_t>::max();
    }
    count *= points;
  }
  return count;
}

std::vector<SweepRun> SweepSpec::expand() const {
  if (const std::size_t count = run_count(); count > kMaxSweepRuns) {
    throw std::length_error("the sweep expands into " +
                            (count == std::numeric_limits<std::size_t>::max()
                                 ? std::string("more than 2^64")
                                 : std::to_string(count)) +
                            " runs; at most " + std::to_string(kMaxSweepRuns) +
                            " are allowed (split it into several sweeps)");
  }
  std::size_t combinations = 1;
  for (const auto& axis : axes) combinations *= axis.points.size();
  std::vector<SweepRun> runs;
  runs.reserve(combinations * seeds.size());
  std::vector<std::size_t> index(axes.size(), 0);
  for (std::size_t c = 0; c < combinations; ++c) {
    // Mixed-radix digits of c, the last axis varying fastest.
    std::size_t rest = c;
    for (std::size_t a = axes.size(); a-- > 0;) {
      index[a] = rest % axes[a].points.size();
      rest /= axes[a].points.size();
    }
    for (const std::uint64_t seed : seeds) {
      SweepRun run;
      run.seed = seed;
      run.point = index;
      for (const auto& fixed : this->fixed) run.set.push_back(fixed.key + "=" + fixed.text);
      for (std::size_t a = 0; a < axes.size(); ++a) {
        const SweepPoint& point = axes[a].points[index[a]];
        for (std::size_t k = 0; k < axes[a].keys.size(); ++k) {
          run.set.push_back(axes[a].keys[k] + "=" + point.values[k].text);
        }
        run.id += axes[a].name + "-" + point.id_part() + "_";
      }
      run.id += "seed-" + std::to_string(seed);
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

}  // namespace swarmnet
