#include "scenario/scenario_checker.hpp"

#include <algorithm>
#include <system_error>

#include "scenario/nearest_name.hpp"
#include "scenario/scalar_rule.hpp"
#include "scenario/shown_value.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

std::string line_column(const YAML::Mark& mark) {
  return std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

// A value's own mark, or its key's when the value is empty (an empty value's mark points past it).
YAML::Mark value_mark(const YAML::Node& value, const YAML::Mark& key_mark) {
  if (value.IsDefined() && !value.IsNull() && !value.Mark().is_null()) return value.Mark();
  return key_mark;
}

// The loader's messages list the places searched on separate lines; a problem is one line.
std::string one_line(std::string text) {
  std::string flat;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') {
      flat += text[i];
      continue;
    }
    std::size_t next = i + 1;
    while (next < text.size() && text[next] == ' ') ++next;
    const bool item = next > i + 1;  // an indented continuation line is a list item
    if (!flat.empty() && flat.back() == ':') {
      flat += ' ';
    } else {
      flat += item ? "; " : " ";
    }
    i = next - 1;
  }
  return flat;
}

YAML::Node empty_map() {
  YAML::Node node(YAML::NodeType::Map);
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

const ScalarRule& plugin_name_rule() {
  static const ScalarRule rule{ScalarType::name, 0, 0, false, false, {}, ""};
  return rule;
}

const ScalarRule& port_rule() {
  static const ScalarRule rule{ScalarType::integer, 0, 65535, false, false, {}, ""};
  return rule;
}

}  // namespace

ScenarioChecker::ScenarioChecker(ProblemList& problems, PluginLoader& loader,
                                 std::filesystem::path base_dir)
    : problems_(problems), loader_(loader), base_dir_(std::move(base_dir)) {}

YAML::Node ScenarioChecker::check_root(const KeySpec& schema, const YAML::Node& root) {
  const Where where{KeyPath{}, root.Mark()};
  return check_map(schema, root, where).value_or(YAML::Node(YAML::NodeType::Map));
}

YAML::Mark ScenarioChecker::mark_of(const KeyPath& path) const {
  const auto it = marks_.find(path.text());
  return it != marks_.end() ? it->second : YAML::Mark::null_mark();
}

std::optional<YAML::Node> checked_node_at(const YAML::Node& tree, const KeyPath& path) {
  YAML::Node node;
  node.reset(tree);
  for (const auto& part : path.parts()) {
    YAML::Node child;
    if (node.IsSequence()) {
      if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos) {
        return std::nullopt;
      }
      const std::size_t index = std::stoul(part);
      if (index >= node.size()) return std::nullopt;
      child = node[index];
    } else if (node.IsMap() && node[part]) {
      child = node[part];
    } else {
      return std::nullopt;
    }
    node.reset(child);
  }
  return node;
}

bool ScenarioChecker::given(const KeyPath& path) const {
  if (!marks_.contains(path.text())) return false;
  for (const auto& defaulted : defaulted_) {
    if (path.starts_with(defaulted)) return false;
  }
  return true;
}

std::optional<YAML::Node> ScenarioChecker::check(const KeySpec& spec, const YAML::Node& value,
                                                 const Where& where) {
  remember(where);
  switch (spec.form) {
    case KeyForm::scalar: {
      std::string problem;
      const auto checked = check_scalar(spec.rule, value, &problem);
      if (!checked) {
        problems_.add(where.path, where.mark, problem, spec.rule.describe());
        return std::nullopt;
      }
      return to_yaml(*checked);
    }
    case KeyForm::map:
      return check_map(spec, value, where);
    case KeyForm::plugin:
      return check_plugin(spec, value, where);
    case KeyForm::directory_list:
    case KeyForm::map_list:
    case KeyForm::plugin_list:
      return check_list(spec, value, where);
  }
  return std::nullopt;
}

std::optional<YAML::Node> ScenarioChecker::check_map(const KeySpec& spec, const YAML::Node& value,
                                                     const Where& where) {
  if (value.IsDefined() && !value.IsNull() && !value.IsMap()) {
    problems_.add(where.path, where.mark, quote_value(value) + " is not a mapping",
                  spec.form == KeyForm::map
                      ? spec.describe()
                      : "a mapping with keys " + join(spec.key_names(), ", "));
    return std::nullopt;
  }
  const std::vector<Entry> given = value.IsMap()
                                       ? entries(value, where, spec.key_names(), "unknown key", "")
                                       : std::vector<Entry>{};
  // Invalid keys are left out: the result holds what later checks can rely on.
  YAML::Node out(YAML::NodeType::Map);
  for (const auto& key : spec.keys) {
    const auto entry = std::find_if(given.begin(), given.end(),
                                    [&key](const Entry& e) { return e.key == key.name; });
    const auto checked = entry != given.end()
                             ? check(key, entry->value, entry->where)
                             : absent(key, Where{where.path / key.name, where.mark});
    if (checked) out[key.name] = *checked;
  }
  if (spec.flow || out.size() == 0) out.SetStyle(YAML::EmitterStyle::Flow);
  return out;
}

std::optional<YAML::Node> ScenarioChecker::absent(const KeySpec& spec, const Where& where) {
  if (spec.is_required()) {
    problems_.add(where.path, where.mark, "missing required key", spec.describe());
    return std::nullopt;
  }
  if (!spec.computed.empty()) return std::nullopt;  // derived after the check
  if (spec.default_yaml) {
    defaulted_.push_back(where.path);
    return check(spec, YAML::Load(*spec.default_yaml), where);
  }
  if (spec.form == KeyForm::map || spec.form == KeyForm::plugin) {
    return check(spec, YAML::Node(YAML::NodeType::Null), where);
  }
  return std::nullopt;
}

std::optional<YAML::Node> ScenarioChecker::check_list(const KeySpec& spec, const YAML::Node& value,
                                                      const Where& where) {
  if (value.IsDefined() && !value.IsNull() && !value.IsSequence()) {
    problems_.add(where.path, where.mark, quote_value(value) + " is not a list", spec.describe());
    return std::nullopt;
  }
  const std::size_t count = value.IsSequence() ? value.size() : 0;
  if (count < spec.min_items) {
    problems_.add(
        where.path, where.mark,
        count == 0 ? std::string("is an empty list") : "has " + std::to_string(count) + " items",
        spec.describe());
    return std::nullopt;
  }
  if (spec.form == KeyForm::directory_list && ignore_directory_lists_) {
    YAML::Node none(YAML::NodeType::Sequence);
    none.SetStyle(YAML::EmitterStyle::Flow);
    return none;
  }
  KeySpec element_spec;  // for map_list: each element is a mapping of spec.keys
  element_spec.form = KeyForm::map;
  element_spec.keys = spec.keys;
  element_spec.flow = spec.flow;

  YAML::Node out(YAML::NodeType::Sequence);
  std::vector<std::filesystem::path> directories;
  bool valid = true;
  for (std::size_t i = 0; i < count; ++i) {
    const YAML::Node element = value[i];
    const Where element_where{where.path / i, value_mark(element, where.mark)};
    remember(element_where);
    const std::size_t problems_before = problems_.size();
    std::optional<YAML::Node> checked;
    switch (spec.form) {
      case KeyForm::directory_list:
        checked = check_directory(element, element_where);
        break;
      case KeyForm::map_list:
        checked = check_map(element_spec, element, element_where);
        break;
      default:
        checked = check_plugin(spec, element, element_where);
        break;
    }
    // A list is usable only whole: one bad element would shift every later index.
    if (!checked || problems_.size() != problems_before) {
      valid = false;
      continue;
    }
    if (spec.form == KeyForm::directory_list) directories.emplace_back(checked->as<std::string>());
    out.push_back(*checked);
  }
  if (!directories.empty()) loader_.prepend_directories(directories);
  if (out.size() == 0) out.SetStyle(YAML::EmitterStyle::Flow);
  if (!valid) return std::nullopt;
  return out;
}

std::optional<YAML::Node> ScenarioChecker::check_directory(const YAML::Node& value,
                                                           const Where& where) {
  static const ScalarRule text_rule{ScalarType::text, 0, 0, false, false, {}, ""};
  const std::string expected =
      "an existing directory (a relative path is relative to the scenario file's directory)";
  std::string problem;
  const auto checked = check_scalar(text_rule, value, &problem);
  if (!checked || std::get<std::string>(*checked).empty()) {
    problems_.add(where.path, where.mark, checked ? "is empty" : problem, expected);
    return std::nullopt;
  }
  const std::string& text = std::get<std::string>(*checked);
  std::filesystem::path dir(text);
  if (dir.is_relative()) dir = base_dir_ / dir;
  std::error_code ec;
  const auto absolute = std::filesystem::absolute(dir, ec);
  if (!ec) dir = absolute;
  dir = dir.lexically_normal();
  if (!dir.has_filename() && dir.has_parent_path()) dir = dir.parent_path();  // no trailing "/"
  if (!std::filesystem::is_directory(dir, ec)) {
    // Where a relative value points; a value cut short would only repeat it at length.
    const std::string resolved = text.size() <= kShownValueChars
                                     ? " (" + shown_value(dir.string(), kShownPathChars) + ")"
                                     : "";
    problems_.add(where.path, where.mark,
                  "'" + shown_value(text) + "'" + resolved + " is not a directory", expected);
    return std::nullopt;
  }
  return YAML::Node(dir.string());
}

std::optional<YAML::Node> ScenarioChecker::check_plugin(const KeySpec& spec,
                                                        const YAML::Node& value,
                                                        const Where& where) {
  const std::string kind = to_string(spec.plugin_kind);
  // A controller entry also has a port (swarmnet/controller.hpp), by default its list index.
  const bool has_port = spec.plugin_kind == PluginKind::controller;
  const std::string form = "{plugin: NAME, params: {...}" +
                           std::string(has_port ? ", port: 0..65535" : "") + "} naming a " + kind +
                           " plugin";
  const bool empty = !value.IsDefined() || value.IsNull();
  if (!empty && !value.IsMap()) {
    problems_.add(where.path, where.mark, quote_value(value) + " is not a mapping", form);
    return std::nullopt;
  }
  if (empty && spec.default_plugin.empty()) {
    problems_.add(where.path, where.mark, "has no value", form);
    return std::nullopt;
  }
  const std::vector<Entry> given =
      empty ? std::vector<Entry>{}
            : entries(value, where,
                      has_port ? std::vector<std::string>{"plugin", "params", "port"}
                               : std::vector<std::string>{"plugin", "params"},
                      "unknown key", "");
  const auto find_entry = [&given](const char* key) -> const Entry* {
    for (const auto& entry : given) {
      if (entry.key == key) return &entry;
    }
    return nullptr;
  };

  // Which plugin.
  const Entry* plugin_entry = find_entry("plugin");
  const KeyPath plugin_path = where.path / "plugin";
  std::string name;
  std::string where_text;
  YAML::Mark plugin_mark = where.mark;
  if (plugin_entry == nullptr) {
    if (spec.default_plugin.empty()) {
      problems_.add(plugin_path, where.mark, "missing required key",
                    "the name of a " + kind + " plugin");
      return std::nullopt;
    }
    name = spec.default_plugin;
    where_text = problems_.file() + " (" + where.path.text() + ": default " + kind + " plugin)";
  } else {
    plugin_mark = plugin_entry->where.mark;
    remember(plugin_entry->where);
    std::string problem;
    const auto checked = check_scalar(plugin_name_rule(), plugin_entry->value, &problem);
    if (!checked) {
      problems_.add(plugin_path, plugin_mark, problem, "the name of a " + kind + " plugin");
      return std::nullopt;
    }
    name = std::get<std::string>(*checked);
    where_text = problems_.locate(plugin_path, plugin_mark);
  }
  std::shared_ptr<PluginLibrary> library;
  try {
    library = loader_.find(name, spec.plugin_kind);
  } catch (const PluginError& error) {
    problems_.add(plugin_path, plugin_mark, one_line(error.what()),
                  "a " + kind + " plugin: " + available_plugins());
    return std::nullopt;
  }

  // Its parameters.
  const Entry* params_entry = find_entry("params");
  const Where params_where =
      params_entry != nullptr ? params_entry->where : Where{where.path / "params", where.mark};
  ParamSet params;
  const auto checked_params =
      check_plugin_params(*library, params_entry != nullptr ? params_entry->value : YAML::Node(),
                          params_where, &params);
  if (!checked_params) return std::nullopt;

  std::int64_t port = 0;
  if (has_port) {
    // An entry of a list: its index is the last part of its path.
    port = std::stoll(where.path.parts().back());
    if (const Entry* port_entry = find_entry("port")) {
      remember(port_entry->where);
      std::string problem;
      const auto checked = check_scalar(port_rule(), port_entry->value, &problem);
      if (!checked) {
        problems_.add(where.path / "port", port_entry->where.mark, problem, port_rule().describe());
        return std::nullopt;
      }
      port = std::get<std::int64_t>(*checked);
    }
  }

  plugins_[where.path.text()] =
      PluginChoice{name, spec.plugin_kind, std::move(params), SourceLocation{where_text}};
  YAML::Node out(YAML::NodeType::Map);
  out["plugin"] = name;
  out["params"] = *checked_params;
  if (has_port) out["port"] = port;
  return out;
}

std::optional<YAML::Node> ScenarioChecker::check_plugin_params(const PluginLibrary& library,
                                                               const YAML::Node& value,
                                                               const Where& where,
                                                               ParamSet* params) {
  const PluginInfo& info = library.info();
  const std::string plugin = "plugin '" + info.name + "'";
  const std::string see = " (see `swarmnet plugins " + info.name + "`)";
  std::vector<std::string> declared;
  for (const auto& spec : info.params) declared.push_back(spec.name);
  if (value.IsDefined() && !value.IsNull() && !value.IsMap()) {
    problems_.add(where.path, where.mark, quote_value(value) + " is not a mapping",
                  "a mapping of " + plugin + "'s parameters" + see);
    return std::nullopt;
  }
  remember(where);
  const std::vector<Entry> given =
      value.IsMap() ? entries(value, where, declared, "not a parameter of " + plugin, see,
                              "no parameters: " + plugin + " declares none")
                    : std::vector<Entry>{};
  bool valid = true;
  // Every default has its declared type: the loader checked the plugin's table when it opened it
  // (plugin/plugin_table_check.hpp).
  for (const auto& spec : info.params) {
    const auto entry = std::find_if(given.begin(), given.end(),
                                    [&spec](const Entry& e) { return e.key == spec.name; });
    if (entry == given.end()) {
      params->set(spec.name, spec.default_value);
      continue;
    }
    remember(entry->where);
    const ScalarRule rule = rule_for(spec);
    std::string problem;
    const auto checked = check_scalar(rule, entry->value, &problem);
    if (!checked) {
      problems_.add(entry->where.path, entry->where.mark, problem, rule.describe());
      valid = false;
      continue;
    }
    params->set(spec.name, *checked);
  }
  if (!valid || given.size() != value.size()) return std::nullopt;
  YAML::Node out = empty_map();
  for (const auto& [name, param] : params->values()) out[name] = to_yaml(param);
  if (out.size() > 0) out.SetStyle(YAML::EmitterStyle::Block);
  return out;
}

std::vector<ScenarioChecker::Entry> ScenarioChecker::entries(
    const YAML::Node& value, const Where& where, const std::vector<std::string>& known,
    const std::string& unknown_what, const std::string& known_hint, const std::string& none_known) {
  std::vector<Entry> result;
  std::map<std::string, YAML::Mark> seen;
  for (auto it = value.begin(); it != value.end(); ++it) {
    const YAML::Node key = it->first;  // a copy: `it->` yields a temporary
    if (!key.IsScalar()) {
      problems_.add(where.path, key.Mark(), "has a key that is not text", "text keys");
      continue;
    }
    const std::string& name = key.Scalar();
    const KeyPath path = where.path / name;
    if (const auto previous = seen.find(name); previous != seen.end()) {
      problems_.add(path, key.Mark(),
                    "is given twice (first at line " + line_column(previous->second) + ")",
                    "each key once");
      continue;
    }
    seen.emplace(name, key.Mark());
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string what = unknown_what;
      if (const auto near = nearest_name(name, known)) what += " (did you mean '" + *near + "'?)";
      problems_.add(path, key.Mark(), what,
                    known.empty() ? none_known : "one of " + join(known, ", ") + known_hint);
      continue;
    }
    result.push_back(Entry{name, it->second, Where{path, value_mark(it->second, key.Mark())}});
  }
  return result;
}

std::string ScenarioChecker::available_plugins() const {
  // Names from file names only: listing them must not run any library's code.
  const std::vector<std::string> names = loader_.names_in_search_path();
  if (names.empty()) return "none is in the search path";
  return "the search path has " + join(names, ", ") + " (`swarmnet plugins` tells their kinds)";
}

}  // namespace swarmnet
