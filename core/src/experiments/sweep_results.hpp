// results.csv of a sweep: one row per run — run_id, seed, status, every swept key, then every
// summary.json field flattened (nested keys joined with '.', e.g. delay_s.p95; lists as JSON
// text; numbers as written in summary.json). Columns appear in a stable order: the fixed ones,
// the grid's keys in file order, then summary fields in the order of their first appearance over
// the runs in expansion order. A run without summary.json has empty summary cells.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/sweep_file.hpp"

namespace swarmnet {

// One cell per leaf of `summary`, keyed "a.b.c", in document order.
std::vector<std::pair<std::string, std::string>> flatten_summary(
    const nlohmann::ordered_json& summary);

// A CSV field, quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

struct SweepRunResult {
  const SweepRun* run = nullptr;
  std::string status;             // ok, failed, not run
  std::filesystem::path summary;  // summary.json (may not exist)
};

std::string results_csv(const SweepSpec& spec, const std::vector<SweepRunResult>& results);

}  // namespace swarmnet
