#include "experiments/sweep_plan.hpp"

#include <fstream>
#include <map>
#include <set>

#include "outputs/output_files.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario_loader.hpp"

namespace swarmnet {

std::vector<std::string> validate_runs(const SweepSpec& spec, const std::vector<SweepRun>& runs) {
  std::map<std::string, std::string> origin;  // "--set KEY" -> sweep file location and value
  for (const auto& fixed : spec.fixed) {
    origin["--set " + fixed.key] = fixed.location + ": set " + fixed.key + "=" + fixed.text;
  }
  std::vector<std::string> problems;
  std::set<std::string> seen;
  PluginLoader loader;
  for (const auto& run : runs) {
    ScenarioOverrides overrides;
    overrides.set = run.set;
    overrides.seed = run.seed;
    overrides.out_dir = "unused";
    try {
      (void)load_scenario(spec.base, overrides, loader);
    } catch (const ScenarioError& error) {
      for (const auto& line : error.problems()) {
        std::string where = "run " + run.id;
        for (std::size_t a = 0; a < spec.axes.size(); ++a) {
          const SweepAxis& axis = spec.axes[a];
          for (std::size_t k = 0; k < axis.keys.size(); ++k) {
            const auto& value = axis.points[run.point[a]].values[k];
            if (line.starts_with("--set " + axis.keys[k] + ":") ||
                line.starts_with("--set " + axis.keys[k] + " ")) {
              where = value.location + ": grid " + (axis.linked ? axis.name + ": " : "") +
                      axis.keys[k] + "=" + value.text;
            }
          }
        }
        for (const auto& [option, place] : origin) {
          if (line.starts_with(option + ":")) where = place;
        }
        if (seen.insert(line).second) problems.push_back(where.append(": ").append(line));
        if (problems.size() >= 20) return problems;
      }
    } catch (const std::exception& error) {
      if (seen.insert(error.what()).second)
        problems.push_back("run " + run.id + ": " + error.what());
    }
  }
  return problems;
}

std::filesystem::path sweep_directory(const SweepSpec& spec, const std::filesystem::path& file,
                                      const std::filesystem::path& out) {
  if (!out.empty()) return out;
  if (!spec.out.empty()) return spec.out;
  return std::filesystem::path("runs/sweeps") / file.stem();
}

std::vector<std::string> run_arguments(const SweepSpec& spec, const SweepRun& run,
                                       const std::filesystem::path& dir) {
  std::vector<std::string> args = {"run", spec.base.string()};
  for (const auto& set : run.set) {
    args.emplace_back("--set");
    args.push_back(set);
  }
  args.insert(args.end(), {"--seed", std::to_string(run.seed), "--out", dir.string(), "--quiet",
                           "--overwrite"});
  return args;
}

std::filesystem::path run_directory(const std::filesystem::path& sweep_dir, const SweepRun& run) {
  return sweep_dir / "runs" / run.id;
}

std::vector<SweepRunResult> finished_runs(const std::vector<SweepRun>& runs,
                                          const std::filesystem::path& sweep_dir) {
  std::vector<SweepRunResult> results(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    results[i].run = &runs[i];
    results[i].summary = run_directory(sweep_dir, runs[i]) / kSummaryFile;
    results[i].status = std::filesystem::exists(results[i].summary) ? "ok" : "not run";
  }
  return results;
}

std::string last_output_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::string last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

}  // namespace swarmnet
