// `swarmnet stats results.csv --by a,b --metric m [--metric m2] [--baseline V] [--within A]
// [--holm] [--bounded] [--json]` (docs/experiments.md): per group of rows with equal --by values
// (named by short labels, group_labels.hpp), n, mean, standard deviation and a 95% confidence
// interval of each metric (Student t; for ratios in [0, 1] one that stays inside,
// proportion_interval.hpp), and Welch's t-test between groups: every pair, or every group against
// --baseline, optionally only between groups that differ in the --within column alone, with
// Holm's correction for the number of comparisons on request.
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
  std::string baseline;              // a group's values joined by ',' ("" : all pairs); with
                                     // `within`, one value of that column
  std::string within;                // compare only groups differing in this --by column alone
  bool holm = false;                 // add Holm-adjusted p-values
  bool bounded = false;              // every metric is a ratio in [0, 1] (pdr and *_ratio always)
  bool json = false;
  double confidence = 0.95;
};

// A CSV file as rows of cells (RFC 4180 quoting); the first row is the header.
std::vector<std::vector<std::string>> read_csv(std::istream& in);

// Exit code: 0, or 2 on a bad file, column or baseline (message on stderr).
int stats_command(const StatsOptions& options, std::ostream& out);

}  // namespace swarmnet
