// `swarmnet stats results.csv --by a,b --metric m [--metric m2] [--baseline V] [--json]`
// (docs/experiments.md): per group of rows with equal --by values, n, mean, standard deviation
// and a 95% Student-t confidence interval of each metric, and Welch's t-test between groups
// (every pair, or every group against --baseline).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace swarmnet {

struct StatsOptions {
  std::filesystem::path file;
  std::vector<std::string> by;       // grouping columns (none: one group)
  std::vector<std::string> metrics;  // numeric columns
  std::string baseline;              // a group's values joined by ',' ("" : all pairs)
  bool json = false;
  double confidence = 0.95;
};

// A CSV file as rows of cells (RFC 4180 quoting); the first row is the header.
std::vector<std::vector<std::string>> read_csv(std::istream& in);

// Exit code: 0, or 2 on a bad file, column or baseline (message on stderr).
int stats_command(const StatsOptions& options, std::ostream& out);

}  // namespace swarmnet
