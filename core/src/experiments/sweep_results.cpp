#include "experiments/sweep_results.hpp"

#include <fstream>
#include <map>
#include <sstream>

namespace swarmnet {

namespace {

void flatten(const nlohmann::ordered_json& node, const std::string& prefix,
             std::vector<std::pair<std::string, std::string>>& cells) {
  if (node.is_object() && !node.empty()) {
    for (const auto& [key, value] : node.items()) {
      flatten(value, prefix.empty() ? key : std::string(prefix).append(".").append(key), cells);
    }
    return;
  }
  std::string text;
  if (node.is_string()) {
    text = node.get<std::string>();
  } else if (!node.is_null()) {
    text = node.dump();
  }
  cells.emplace_back(prefix, std::move(text));
}

}  // namespace

std::vector<std::pair<std::string, std::string>> flatten_summary(
    const nlohmann::ordered_json& summary) {
  std::vector<std::pair<std::string, std::string>> cells;
  flatten(summary, "", cells);
  return cells;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string results_csv(const SweepSpec& spec, const std::vector<SweepRunResult>& results) {
  std::vector<std::string> columns = {"run_id", "seed", "status"};
  for (const auto& axis : spec.axes) {
    columns.insert(columns.end(), axis.keys.begin(), axis.keys.end());
  }
  const std::size_t fixed_columns = columns.size();
  std::map<std::string, std::size_t> column_of;
  for (std::size_t i = 0; i < columns.size(); ++i) column_of.emplace(columns[i], i);

  std::vector<std::map<std::size_t, std::string>> rows;
  for (const auto& result : results) {
    std::map<std::size_t, std::string> row;
    row[0] = result.run->id;
    row[1] = std::to_string(result.run->seed);
    row[2] = result.status;
    std::size_t column = 3;
    for (std::size_t a = 0; a < spec.axes.size(); ++a) {
      for (const auto& value : spec.axes[a].points[result.run->point[a]].values) {
        row[column++] = value.text;
      }
    }
    std::ifstream in(result.summary);
    if (in) {
      nlohmann::ordered_json summary;
      try {
        summary = nlohmann::ordered_json::parse(in);
      } catch (const nlohmann::json::exception&) {
        summary = nullptr;
      }
      if (summary.is_object()) {
        for (auto& [key, text] : flatten_summary(summary)) {
          auto [it, added] = column_of.emplace(key, columns.size());
          if (added) {
            columns.push_back(key);
          } else if (it->second < fixed_columns) {
            continue;  // seed: already a column of its own
          }
          row[it->second] = std::move(text);
        }
      }
    }
    rows.push_back(std::move(row));
  }

  std::ostringstream out;
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csv_field(columns[i]);
  out << '\n';
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out << ',';
      if (const auto it = row.find(i); it != row.end()) out << csv_field(it->second);
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace swarmnet
