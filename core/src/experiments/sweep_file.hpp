// A sweep file (docs/experiments.md): a base scenario, fixed overrides, a grid of overrides whose
// cartesian product is run (each axis one key, or several linked keys that vary together), and a
// list of seeds. Read, checked (every problem at once, as "FILE:LINE:COLUMN: KEY: what is wrong;
// expected FORM", like a scenario) and expanded into runs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace swarmnet {

// Every problem found in a sweep file, one per line.
class SweepError : public std::runtime_error {
 public:
  explicit SweepError(std::vector<std::string> problems);
  [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// One value of a swept key, as given to --set and as written in results.csv.
struct SweepValue {
  std::string text;      // YAML flow form: 50, aodv, {plugin: aodv}
  std::string id_part;   // readable form for run ids: 50, aodv
  std::string location;  // FILE:LINE:COLUMN of the value in the sweep file
};

// One position along an axis: a value for each of the axis's keys.
struct SweepPoint {
  std::vector<SweepValue> values;  // in the order of SweepAxis::keys
  // The point's part of a run id: its first key's value's id_part.
  [[nodiscard]] const std::string& id_part() const { return values.front().id_part; }
};

// A grid axis. A plain axis sweeps one key; a linked axis sweeps several keys together (the i-th
// values of every key make its i-th point), e.g. robots.count with the arena's size so that the
// density stays constant.
struct SweepAxis {
  std::string name;               // its name in run ids: count, routing, or a linked axis's name
  std::vector<std::string> keys;  // scenario key paths, e.g. robots.count; one unless linked
  std::vector<SweepPoint> points;
  bool linked = false;
};

struct SweepFixed {
  std::string key;
  std::string text;
  std::string location;
};

struct SweepRun {
  std::string id;  // e.g. count-50_routing-aodv_seed-3
  std::uint64_t seed = 0;
  std::vector<std::size_t> point;  // index into each axis's points
  std::vector<std::string> set;    // --set arguments (fixed ones first, then the grid's)
};

// The most runs one sweep may expand into (each is a directory and a process): far beyond any
// study, far below what exhausts memory.
inline constexpr std::size_t kMaxSweepRuns = 1'000'000;

struct SweepSpec {
  std::filesystem::path file;
  std::filesystem::path base;  // absolute
  std::filesystem::path out;   // as written ("" when not given)
  std::vector<SweepFixed> fixed;
  std::vector<SweepAxis> axes;
  std::vector<std::uint64_t> seeds;

  // How many runs expand() gives, counted without building them (saturates at SIZE_MAX).
  [[nodiscard]] std::size_t run_count() const;
  // Every run, in a stable order: axes in file order (the first varies slowest), then seeds.
  // Throws std::length_error for more than kMaxSweepRuns runs.
  [[nodiscard]] std::vector<SweepRun> expand() const;
};

// Reads and checks `file`; throws SweepError listing every problem.
SweepSpec load_sweep(const std::filesystem::path& file);

}  // namespace swarmnet
