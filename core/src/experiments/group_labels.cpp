#include "experiments/group_labels.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace swarmnet {

namespace {

// A mapping's entries as (path, value text) in order, `plugin` kept apart.
struct Entries {
  std::optional<std::string> plugin;
  std::vector<std::pair<std::string, std::string>> leaves;
};

std::string flow_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

void flatten(const YAML::Node& map, const std::string& prefix, Entries& entries) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    // Under `params` a key is a plugin parameter: its name alone says what it is.
    const std::string path = prefix.empty() || prefix == "params" ? key : prefix + "." + key;
    if (prefix.empty() && key == "plugin" && it->second.IsScalar()) {
      entries.plugin = it->second.Scalar();
    } else if (it->second.IsMap()) {
      flatten(it->second, prefix.empty() ? key : prefix + "." + key, entries);
    } else {
      entries.leaves.emplace_back(path, flow_text(it->second));
    }
  }
}

std::optional<Entries> mapping_entries(const std::string& text) {
  if (text.empty() || text.front() != '{') return std::nullopt;
  try {
    const YAML::Node node = YAML::Load(text);
    if (!node.IsMap()) return std::nullopt;
    Entries entries;
    flatten(node, "", entries);
    return entries;
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::vector<std::string> short_labels(const std::vector<std::string>& values) {
  std::vector<std::optional<Entries>> parsed;
  parsed.reserve(values.size());
  for (const auto& value : values) parsed.push_back(mapping_entries(value));

  // Per plugin (mappings without one together), the entries whose value is not the same in
  // each of its mappings; an entry some of them lack differs too.
  std::map<std::string, std::map<std::string, std::set<std::string>>> seen;
  std::map<std::string, std::map<std::string, std::size_t>> holders;
  std::map<std::string, std::size_t> mappings;
  for (const auto& entries : parsed) {
    if (!entries) continue;
    const std::string plugin = entries->plugin.value_or("");
    ++mappings[plugin];
    for (const auto& [path, text] : entries->leaves) {
      seen[plugin][path].insert(text);
      ++holders[plugin][path];
    }
  }
  std::map<std::string, std::set<std::string>> differing;
  for (const auto& [plugin, paths] : seen) {
    for (const auto& [path, texts] : paths) {
      if (texts.size() > 1 || holders[plugin][path] != mappings[plugin])
        differing[plugin].insert(path);
    }
  }

  std::vector<std::string> labels;
  labels.reserve(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!parsed[i]) {
      labels.push_back(values[i]);
      continue;
    }
    std::string label = parsed[i]->plugin.value_or("");
    const auto& differs = differing[label];
    const bool all = label.empty() &&
                     std::none_of(parsed[i]->leaves.begin(), parsed[i]->leaves.end(),
                                  [&](const auto& leaf) { return differs.contains(leaf.first); });
    for (const auto& [path, text] : parsed[i]->leaves) {
      if (!all && !differs.contains(path)) continue;
      label += (label.empty() ? "" : " ") + path + "=" + text;
    }
    labels.push_back(label.empty() ? values[i] : label);
  }

  // Two different values with one name keep their full text.
  std::map<std::string, std::set<std::string>> values_of;
  for (std::size_t i = 0; i < values.size(); ++i) values_of[labels[i]].insert(values[i]);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values_of[labels[i]].size() > 1) labels[i] = values[i];
  }
  return labels;
}

}  // namespace swarmnet
