#include "experiments/stats_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "experiments/group_labels.hpp"
#include "session/exit_codes.hpp"
#include "stats/holm_correction.hpp"
#include "stats/proportion_interval.hpp"
#include "stats/sample_statistics.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

std::string number(double value, int precision = 6) {
  if (std::isnan(value)) return "-";
  std::ostringstream text;
  text << std::setprecision(precision) << value;
  return text.str();
}

nlohmann::ordered_json json_number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

void print_table(std::ostream& out, const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (std::size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  }
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) line += "  ";
      line += row[i];
      if (i + 1 < row.size()) line.append(width[i] - row[i].size(), ' ');
    }
    out << line << '\n';
  }
}

// Metrics that are ratios in [0, 1] by definition: their intervals are kept inside it.
bool is_proportion_metric(const std::string& metric) {
  return metric == "pdr" || metric.ends_with("_ratio") || metric.ends_with(".ratio");
}

struct Group {
  std::vector<std::string> key;
  std::map<std::string, std::vector<double>> values;  // metric -> values
};

}  // namespace

std::vector<std::vector<std::string>> read_csv(std::istream& in) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string cell;
  bool quoted = false;
  bool any = false;
  char c = 0;
  while (in.get(c)) {
    any = true;
    if (quoted) {
      if (c == '"') {
        if (in.peek() == '"') {
          cell += '"';
          in.get(c);
        } else {
          quoted = false;
        }
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(std::move(cell));
      cell.clear();
    } else if (c == '\n') {
      row.push_back(std::move(cell));
      cell.clear();
      rows.push_back(std::move(row));
      row.clear();
      any = false;
    } else if (c != '\r') {
      cell += c;
    }
  }
  if (any) {
    row.push_back(std::move(cell));
    rows.push_back(std::move(row));
  }
  return rows;
}

int stats_command(const StatsOptions& options, std::ostream& out) {
  auto fail = [](const std::string& message) {
    std::fprintf(stderr, "swarmnet: error: %s\n", message.c_str());
    return kExitBadInput;
  };
  std::ifstream in(options.file);
  if (!in) return fail("cannot read " + options.file.string());
  const auto rows = read_csv(in);
  if (rows.empty()) return fail(options.file.string() + ": empty file");
  const auto& header = rows.front();
  auto column = [&](const std::string& name) -> std::ptrdiff_t {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return static_cast<std::ptrdiff_t>(i);
    }
    return -1;
  };
  std::vector<std::size_t> by;
  std::vector<std::size_t> metric_columns;
  for (const auto& name : options.by) {
    const auto i = column(name);
    if (i < 0) return fail(options.file.string() + ": no column '" + name + "' (--by)");
    by.push_back(static_cast<std::size_t>(i));
  }
  for (const auto& name : options.metrics) {
    const auto i = column(name);
    if (i < 0) return fail(options.file.string() + ": no column '" + name + "' (--metric)");
    metric_columns.push_back(static_cast<std::size_t>(i));
  }

  std::vector<Group> groups;
  std::map<std::vector<std::string>, std::size_t> group_of;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    std::vector<std::string> key;
    key.reserve(by.size());
    for (const std::size_t i : by) key.push_back(i < row.size() ? row[i] : "");
    auto [it, added] = group_of.emplace(key, groups.size());
    if (added) groups.push_back({key, {}});
    Group& group = groups[it->second];
    for (std::size_t m = 0; m < metric_columns.size(); ++m) {
      auto& values = group.values[options.metrics[m]];
      const std::size_t i = metric_columns[m];
      if (i >= row.size() || row[i].empty()) continue;  // a failed run, or no value
      std::size_t used = 0;
      double value = 0.0;
      try {
        value = std::stod(row[i], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != row[i].size()) {
        return fail(options.file.string() + ":" + std::to_string(r + 1) + ": column '" +
                    options.metrics[m] + "': '" + row[i] + "' is not a number");
      }
      values.push_back(value);
    }
  }

  // Short names per --by column (group_labels.hpp): a group's label joins its columns' names.
  std::vector<std::vector<std::string>> names(groups.size(), std::vector<std::string>(by.size()));
  for (std::size_t c = 0; c < by.size(); ++c) {
    std::vector<std::string> column_values;
    for (const auto& g : groups) column_values.push_back(g.key[c]);
    const auto labels = short_labels(column_values);
    for (std::size_t g = 0; g < groups.size(); ++g) names[g][c] = labels[g];
  }
  auto label = [&](std::size_t g) { return by.empty() ? std::string("all") : join(names[g], ","); };

  std::optional<std::size_t> within;
  if (!options.within.empty()) {
    for (std::size_t c = 0; c < options.by.size(); ++c) {
      if (options.by[c] == options.within) within = c;
    }
    if (!within) {
      return fail("--within " + options.within + ": not one of the --by columns (" +
                  join(options.by, ", ") + ")");
    }
  }
  // The groups --baseline names: one group, or with --within a value of that column (a group
  // in each stratum). Short names and full texts both match.
  std::vector<bool> is_baseline(groups.size(), false);
  if (!options.baseline.empty()) {
    std::set<std::string> known;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const bool match =
          within
              ? names[g][*within] == options.baseline || groups[g].key[*within] == options.baseline
              : label(g) == options.baseline || join(groups[g].key, ",") == options.baseline;
      is_baseline[g] = match;
      known.insert(within ? names[g][*within] : label(g));
    }
    if (std::find(is_baseline.begin(), is_baseline.end(), true) == is_baseline.end()) {
      return fail("--baseline " + options.baseline + ": no such " +
                  (within ? "value of " + options.within : std::string("group")) + "; there are: " +
                  join(std::vector<std::string>(known.begin(), known.end()), "; "));
    }
  }
  // Which pairs are compared: all, or against the baseline; with --within only groups that
  // agree on every other --by column, so that each comparison changes one factor.
  auto same_stratum = [&](std::size_t a, std::size_t b) {
    if (!within) return true;
    for (std::size_t c = 0; c < by.size(); ++c) {
      if (c != *within && groups[a].key[c] != groups[b].key[c]) return false;
    }
    return true;
  };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < groups.size(); ++a) {
    for (std::size_t b = a + 1; b < groups.size(); ++b) {
      if (!same_stratum(a, b)) continue;
      if (options.baseline.empty()) {
        pairs.emplace_back(a, b);
      } else if (is_baseline[a] != is_baseline[b]) {
        pairs.emplace_back(is_baseline[a] ? a : b, is_baseline[a] ? b : a);
      }
    }
  }
  const std::string ci_name = number(100.0 * options.confidence) + "%";

  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  json["file"] = options.file.string();
  json["by"] = options.by;
  json["confidence"] = options.confidence;
  if (!options.within.empty()) json["within"] = options.within;
  if (!options.baseline.empty()) json["baseline"] = options.baseline;
  json["holm"] = options.holm;
  json["metrics"] = nlohmann::ordered_json::object();
  for (const auto& metric : options.metrics) {
    const bool bounded = options.bounded || is_proportion_metric(metric);
    if (bounded) {
      for (const auto& group : groups) {
        for (const double v : group.values.at(metric)) {
          if (v < 0.0 || v > 1.0) {
            return fail(options.file.string() + ": column '" + metric + "' has " + number(v) +
                        ", outside [0, 1]: its interval cannot be bounded (" +
                        (options.bounded ? "drop --bounded" : "a ratio should not") + ")");
          }
        }
      }
    }
    const std::string interval = bounded ? " (Wilson)" : "";
    std::vector<std::vector<std::string>> table;
    std::vector<std::string> head = options.by;
    if (head.empty()) head.emplace_back("group");
    head.insert(head.end(), {"n", "mean", "sd", ci_name + " CI low" + interval,
                             ci_name + " CI high" + interval});
    table.push_back(head);
    nlohmann::ordered_json jgroups = nlohmann::ordered_json::array();
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const auto& values = groups[g].values.at(metric);
      const stats::SampleSummary s = bounded
                                         ? stats::summarize_proportions(values, options.confidence)
                                         : stats::summarize(values, options.confidence);
      std::vector<std::string> line = by.empty() ? std::vector<std::string>{"all"} : names[g];
      line.insert(line.end(), {std::to_string(s.n), number(s.mean), number(s.sd), number(s.ci_low),
                               number(s.ci_high)});
      table.push_back(line);
      nlohmann::ordered_json jg;
      jg["group"] = nlohmann::ordered_json::object();
      for (std::size_t i = 0; i < by.size(); ++i) jg["group"][options.by[i]] = groups[g].key[i];
      jg["label"] = label(g);
      jg["n"] = s.n;
      jg["mean"] = json_number(s.mean);
      jg["sd"] = json_number(s.sd);
      jg["ci_low"] = json_number(s.ci_low);
      jg["ci_high"] = json_number(s.ci_high);
      jgroups.push_back(jg);
    }
    std::vector<stats::WelchTest> welch;
    std::vector<double> p;
    for (const auto& [a, b] : pairs) {
      welch.push_back(stats::welch_test(groups[a].values.at(metric), groups[b].values.at(metric)));
      p.push_back(welch.back().p);
    }
    const std::vector<double> p_holm = stats::holm_adjust(p);
    std::vector<std::string> test_head = {"group A", "group B", "t", "df", "p"};
    if (options.holm) test_head.emplace_back("p (Holm)");
    std::vector<std::vector<std::string>> tests = {test_head};
    nlohmann::ordered_json jtests = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto [a, b] = pairs[i];
      const stats::WelchTest& w = welch[i];
      tests.push_back({label(a), label(b), number(w.t, 4), number(w.df, 4), number(w.p, 4)});
      if (options.holm) tests.back().push_back(number(p_holm[i], 4));
      nlohmann::ordered_json jt = {{"a", label(a)},
                                   {"b", label(b)},
                                   {"t", json_number(w.t)},
                                   {"df", json_number(w.df)},
                                   {"p", json_number(w.p)}};
      if (options.holm) jt["p_holm"] = json_number(p_holm[i]);
      jtests.push_back(jt);
    }
    json["metrics"][metric] = {{"interval", bounded ? "wilson_effective_n" : "student_t"},
                               {"groups", jgroups},
                               {"welch", jtests}};
    if (!options.json) {
      out << metric << '\n';
      print_table(out, table);
      if (!pairs.empty()) {
        out << "\nWelch's t-test of " << metric << " (two-sided), " << pairs.size()
            << (pairs.size() == 1 ? " comparison" : " comparisons")
            << (options.holm       ? "; p (Holm): corrected for all of them"
                : pairs.size() > 1 ? "; p not corrected for multiple comparisons "
                                     "(--holm corrects)"
                                   : "")
            << '\n';
        print_table(out, tests);
      }
      out << '\n';
    }
  }
  if (options.json) out << json.dump(2) << '\n';
  return 0;
}

}  // namespace swarmnet
