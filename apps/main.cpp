// The swarmnet command: run, validate, plugins, sweep, stats, plot, replay, view, bench.
#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bench_command.hpp"
#include "coupling/memory_budget.hpp"
#include "coupling/network_process.hpp"
#include "coupling/stop_signal.hpp"
#include "default_scenario.hpp"
#include "display/summary_printout.hpp"
#include "experiments/stats_command.hpp"
#include "experiments/sweep_command.hpp"
#include "outputs/output_files.hpp"
#include "outputs/run_directory.hpp"
#include "plot_command.hpp"
#include "plugin/plugin_catalog.hpp"
#include "plugin/plugin_loader.hpp"
#include "replay_command.hpp"
#include "scenario/scenario_loader.hpp"
#include "scenario/shown_value.hpp"
#include "session/exit_codes.hpp"
#include "session/run.hpp"
#include "view_command.hpp"
#include "viewer/view_page.hpp"

namespace {

// The longest command-line refusal printed whole (a refused value is cut beyond it).
constexpr std::size_t kShownMessageChars = 400;

using swarmnet::kExitBadInput;
using swarmnet::kExitRunFailed;

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "swarmnet: error: %s\n", message.c_str());
  return code;
}

struct ScenarioArguments {
  std::string file;
  std::vector<std::string> set;
  std::optional<std::uint64_t> seed;
  std::optional<std::string> out;
};

void add_scenario_options(CLI::App* command, ScenarioArguments& args, bool with_outputs) {
  command
      ->add_option("--set", args.set,
                   "override a scenario value, e.g. --set robots.count=100 (repeatable)")
      ->type_name("KEY.PATH=VALUE");
  // Read as text: CLI11 would wrap "-1" into 2^64-1 for an unsigned option.
  command
      ->add_option_function<std::string>(
          "--seed",
          [&args](const std::string& text) {
            std::uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [rest, error] = std::from_chars(text.data(), end, value);
            if (text.empty() || text[0] == '-' || error != std::errc() || rest != end ||
                value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
              throw CLI::ValidationError("--seed", "'" + text +
                                                       "' is not a seed; expected an integer "
                                                       "0..9223372036854775807");
            }
            args.seed = value;
          },
          "master random seed, 0..2^63-1 (overrides the file's seed)")
      ->type_name("UINT");
  if (with_outputs)
    command->add_option("--out", args.out, "run directory (default runs/NAME-seedSEED)");
}

// Validates the scenario; `loader` resolves its plugins and is the one the run creates them with.
swarmnet::Scenario load(const ScenarioArguments& args, swarmnet::PluginLoader& loader) {
  swarmnet::ScenarioOverrides overrides;
  overrides.set = args.set;
  overrides.seed = args.seed;
  if (args.out) overrides.out_dir = *args.out;
  return swarmnet::load_scenario(args.file, overrides, loader);
}

struct TransportArguments {
  std::string kind = "shm";
  std::string remote;
  std::string token_file;
  double step_timeout_s = 60.0;
};

int run_command(ScenarioArguments args, bool quiet, bool overwrite, bool view,
                const TransportArguments& transport) {
  if (args.file.empty()) args.file = swarmnet::default_scenario_path().string();
  swarmnet::PluginLoader loader;
  swarmnet::Scenario scenario;
  try {
    scenario = load(args, loader);
  } catch (const std::exception& error) {
    return fail(kExitBadInput, error.what());
  }
  try {
    swarmnet::RunOptions options;
    options.progress = quiet ? nullptr : stderr;
    options.overwrite = overwrite;
    options.link.kind = *swarmnet::parse_transport_kind(transport.kind);
    options.link.remote = transport.remote;
    options.link.token_file = transport.token_file;
    options.link.step_timeout =
        std::chrono::milliseconds(std::llround(transport.step_timeout_s * 1e3));
    swarmnet::install_stop_handlers();
    const auto outcome = swarmnet::run_scenario(scenario, loader, options);
    if (!quiet) swarmnet::print_summary(stdout, outcome.summary, outcome.dir);
    if (view) {
      const std::filesystem::path page = outcome.dir / swarmnet::kViewPageFile;
      try {
        swarmnet::write_view_page(outcome.dir, page);
      } catch (const std::exception& error) {
        return fail(kExitRunFailed, std::string("the run finished, but its page (--view) could "
                                                "not be written: ") +
                                        error.what());
      }
      if (!quiet) std::printf("viewer: %s\n", page.c_str());
    }
  } catch (const std::exception& error) {
    const int signal = swarmnet::stop_signal();
    return fail(signal != 0 ? 128 + signal : kExitRunFailed, error.what());
  }
  return 0;
}

int clean_command(const std::vector<std::string>& dirs) {
  for (const std::string& dir : dirs) {
    const auto removed = swarmnet::remove_leftover_files(dir);
    std::printf("%s: removed %zu temporary file(s) an interrupted run left\n", dir.c_str(),
                removed.size());
    for (const auto& path : removed) std::printf("  %s\n", path.filename().c_str());
  }
  return 0;
}

int validate_command(const ScenarioArguments& args) {
  try {
    swarmnet::PluginLoader loader;
    const swarmnet::Scenario scenario = load(args, loader);
    std::printf(
        "%s: valid scenario '%s': %u robots, %llu steps of %g s, %zu controller(s), "
        "routing %s over %s\n",
        args.file.c_str(), scenario.name.c_str(), scenario.robots.count,
        static_cast<unsigned long long>(scenario.step_count()), scenario.step_s,
        scenario.robots.controllers.size(), scenario.network.routing.name.c_str(),
        scenario.network.mac.name.c_str());
  } catch (const std::exception& error) {
    return fail(kExitBadInput, error.what());
  }
  return 0;
}

int plugins_command(const std::string& name) {
  try {
    swarmnet::PluginLoader loader;
    if (name.empty()) {
      swarmnet::print_plugin_table(std::cout, loader);
    } else {
      swarmnet::print_plugin_details(std::cout, *loader.find(name));
    }
  } catch (const std::exception& error) {
    return fail(kExitBadInput, error.what());
  }
  return 0;
}

}  // namespace

static int run_main(int argc, char** argv) {
  CLI::App app{"SwarmNet: networked robot swarms, robot and network co-simulation"};
  // Named here, not from argv[0]: `help` prints before parsing, and a path would be noise.
  app.name("swarmnet");
  app.require_subcommand(1);
  // The plugin ABI too: a plugin built against another SDK is refused, and this says which.
  app.set_version_flag("--version", std::string("swarmnet ") + SWARMNET_VERSION +
                                        " (plugin ABI version " +
                                        std::to_string(swarmnet::kAbiVersion) + ")");

  ScenarioArguments run_args;
  bool quiet = false;
  auto* run = app.add_subcommand("run", "run a scenario (configs/quickstart.yaml by default)");
  run->add_option("file", run_args.file, "scenario file")->check(CLI::ExistingFile);
  add_scenario_options(run, run_args, true);
  run->add_flag("-q,--quiet", quiet, "print nothing but errors");
  bool run_view = false;
  run->add_flag("--view", run_view,
                "write the replay page view.html into the run directory at the end (needs "
                "output.mobility_trace; docs/viewer.md)");
  bool overwrite = false;
  run->add_flag("--overwrite", overwrite,
                "replace an earlier run in the run directory (without it, such a directory is "
                "refused)");
  TransportArguments transport;
  run->add_option("--transport", transport.kind,
                  "how the two halves talk: shm (two processes, shared memory), inproc (threads), "
                  "uds (Unix socket), tcp (TCP loopback)")
      ->check(CLI::IsMember({"shm", "inproc", "uds", "tcp"}))
      ->capture_default_str();
  run->add_option("--net", transport.remote,
                  "use a network half started with 'swarmnet net --listen' (tcp://HOST:PORT)");
  run->add_option("--token-file", transport.token_file,
                  "with --net: the token the network half was started with (default: "
                  "$SWARMNET_NET_TOKEN_FILE)");
  run->add_option("--step-timeout", transport.step_timeout_s,
                  "seconds the other half may go without answering before it is declared "
                  "hung; a network half this run started is hung only if it also used no CPU "
                  "in that time (a long step is waited for)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  swarmnet::NetworkProcessOptions net_options;
  double net_timeout_ms = 60000.0;
  std::string net_out;
  auto* net = app.add_subcommand(
      "net", "the network half as a process of its own (started by 'run', or with --listen)");
  auto* source = net->add_option_group("connection", "how to reach the robot half");
  source->add_option("--shm", net_options.shm, "shared-memory segment to attach to");
  source->add_option("--uds", net_options.uds, "Unix socket to connect to");
  source->add_option("--tcp", net_options.tcp, "HOST:PORT to connect to");
  source->add_option("--listen", net_options.listen,
                     "serve robot halves on [HOST:]PORT (HOST defaults to 127.0.0.1)");
  source->require_option(1);
  net->add_option("--parent", net_options.parent, "stop when this process is gone");
  net->add_option("--step-timeout-ms", net_timeout_ms,
                  "milliseconds the robot half may go without answering (and, for the parent "
                  "of a child network half, without using CPU) before it is declared hung")
      ->check(CLI::PositiveNumber);
  net->add_option("--out", net_out,
                  "with --listen: directory for the runs served (run-NNNN each; default "
                  "$XDG_STATE_HOME/swarmnet/net or ~/.local/state/swarmnet/net)");
  net->add_option("--token-file", net_options.token_file,
                  "with --listen: a private file whose contents robot halves must prove they "
                  "know (default: $SWARMNET_NET_TOKEN_FILE; required)");
  std::vector<std::string> net_plugin_paths;
  net->add_option("--plugin-path", net_plugin_paths,
                  "with --listen: a plugin directory searched first (repeatable); a robot half's "
                  "plugin_paths are never used");
  net->add_option("--runs", net_options.runs, "with --listen: runs to serve, then exit")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  net->add_flag("--serve-forever", net_options.serve_forever,
                "with --listen: serve runs until stopped (SIGINT/SIGTERM)");
  double handshake_timeout_s = 5.0;
  net->add_option("--handshake-timeout", handshake_timeout_s,
                  "with --listen: seconds a connecting peer has to authenticate and say hello")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  net->add_option("--max-pending-handshakes", net_options.max_pending_handshakes,
                  "with --listen: handshakes in flight at once; a connection beyond them drops "
                  "the oldest pending one from the busiest address")
      ->check(CLI::Range(1U, 4096U))
      ->capture_default_str();
  auto* net_max_memory =
      net->add_option("--max-memory", net_options.max_memory,
                      "with --listen: memory the runs served may take, e.g. 4G or 512MiB (binary "
                      "units; default: half the host's physical memory); a scenario that needs "
                      "more is refused")
          ->transform(CLI::AsSizeValue(false))
          ->check(CLI::Range(std::uint64_t{1}, std::numeric_limits<std::uint64_t>::max()));

  ScenarioArguments validate_args;
  auto* validate = app.add_subcommand("validate", "check a scenario without running it");
  validate->add_option("file", validate_args.file, "scenario file")->required();
  add_scenario_options(validate, validate_args, true);

  std::string plugin_name;
  auto* plugins = app.add_subcommand("plugins", "list plugins, or describe one");
  plugins->add_option("name", plugin_name, "plugin to describe");

  swarmnet::SweepOptions sweep_options;
  std::string sweep_file;
  std::string sweep_out;
  auto* sweep = app.add_subcommand(
      "sweep", "run a grid of scenario overrides times seeds in parallel (docs/experiments.md)");
  sweep->add_option("file", sweep_file, "sweep file")->required()->check(CLI::ExistingFile);
  sweep->add_option("-j,--jobs", sweep_options.jobs, "runs at once (default: number of cores)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--out", sweep_out,
                    "sweep directory (default: the file's out, else runs/sweeps/NAME)");
  auto* sweep_check =
      sweep->add_flag("--check", sweep_options.validate_only,
                      "validate the sweep and every scenario it expands to, run nothing");
  bool sweep_slurm = false;
  bool sweep_status = false;
  bool sweep_collect = false;
  std::string sweep_swarmnet;
  auto* slurm_flag = sweep->add_flag(
      "--slurm", sweep_slurm,
      "submit the unfinished runs to Slurm as one job array (again: only what is missing or "
      "failed); prints the job id");
  auto* status_flag =
      sweep->add_flag("--status", sweep_status,
                      "show done, running, pending and failed runs (run directories, Slurm)");
  auto* collect_flag =
      sweep->add_flag("--collect", sweep_collect,
                      "write results.csv from the run directories, as a local sweep does");
  slurm_flag->excludes(status_flag)->excludes(collect_flag)->excludes(sweep_check);
  status_flag->excludes(collect_flag)->excludes(sweep_check);
  collect_flag->excludes(sweep_check);
  sweep->add_option("--partition", sweep_options.slurm.partition, "Slurm partition (--slurm)")
      ->needs(slurm_flag);
  sweep
      ->add_option("--time", sweep_options.slurm.time_limit,
                   "time limit of each run, as sbatch --time takes it (--slurm)")
      ->needs(slurm_flag);
  sweep
      ->add_option("--cpus-per-run", sweep_options.slurm.cpus_per_run,
                   "CPUs each run asks for (--slurm; default 1)")
      ->check(CLI::PositiveNumber)
      ->needs(slurm_flag);
  sweep
      ->add_option("--max-parallel", sweep_options.slurm.max_parallel,
                   "at most K runs of the array at once (--slurm; default: no limit)")
      ->check(CLI::PositiveNumber)
      ->needs(slurm_flag);
  sweep
      ->add_option("--sbatch-arg", sweep_options.slurm.sbatch_args,
                   "one more sbatch option for the job array, e.g. --sbatch-arg=--account=abc "
                   "(--slurm; repeatable)")
      ->allow_extra_args(false)
      ->needs(slurm_flag);
  sweep
      ->add_option("--swarmnet", sweep_swarmnet,
                   "the swarmnet the cluster's nodes run (--slurm; default: $SWARMNET_SLURM_BIN, "
                   "else this one)")
      ->needs(slurm_flag);

  swarmnet::StatsOptions stats_options;
  std::string stats_file;
  std::string stats_by;
  auto* stats = app.add_subcommand(
      "stats", "per-group mean, sd, 95% confidence interval and Welch's t-tests of a results.csv");
  stats->add_option("file", stats_file, "results.csv of a sweep")
      ->required()
      ->check(CLI::ExistingFile);
  stats->add_option("--by", stats_by, "columns that define the groups, comma-separated");
  stats->add_option("--metric", stats_options.metrics, "numeric column to summarise (repeatable)")
      ->required();
  stats->add_option("--baseline", stats_options.baseline,
                    "compare every group against this one (its labels as printed, "
                    "comma-separated; with --within, one value of that column) instead of all "
                    "pairs");
  stats->add_option("--within", stats_options.within,
                    "compare only groups that differ in this --by column alone (one factor at "
                    "a time, the others held equal)");
  stats->add_flag("--holm", stats_options.holm,
                  "add p-values corrected for the number of comparisons (Holm's step-down)");
  stats->add_flag("--bounded", stats_options.bounded,
                  "every metric is a ratio in [0, 1]: intervals stay inside it (Wilson with an "
                  "effective n; automatic for pdr and *_ratio)");
  stats->add_flag("--json", stats_options.json, "machine-readable output");

  swarmnet::ReplayCommandOptions replay_options;
  std::string replay_dir;
  std::string replay_out;
  std::string replay_scenario;
  std::string replay_positions;
  std::string replay_traffic;
  auto* replay = app.add_subcommand(
      "replay", "the network half alone, from a run's recorded motion and traffic");
  replay->add_option("run_dir", replay_dir, "run directory (scenario, positions.bin, traffic.csv)")
      ->check(CLI::ExistingDirectory);
  replay->add_option("--scenario", replay_scenario, "resolved scenario (scenario.resolved.yaml)")
      ->check(CLI::ExistingFile);
  replay->add_option("--positions", replay_positions, "exact positions record (positions.bin)")
      ->check(CLI::ExistingFile);
  replay->add_option("--traffic", replay_traffic, "traffic schedule (traffic.csv)")
      ->check(CLI::ExistingFile);
  replay->add_option("--out", replay_out, "output directory (default RUN_DIR/replay)");
  replay->add_flag("-q,--quiet", replay_options.quiet, "print nothing but errors");

  swarmnet::ViewCommandOptions view_options;
  auto* view = app.add_subcommand(
      "view",
      "a run's replay in one self-contained HTML page, and videos and figures of it "
      "(docs/viewer.md)");
  view->add_option("run_dir", view_options.run_dir, "run directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  view->add_option("--out", view_options.out, "the page (default RUN_DIR/view.html)");
  auto* video = view->add_option("--video", view_options.video,
                                 "also render a video (MP4, H.264) with headless Chromium and "
                                 "ffmpeg");
  view->add_option("--fps", view_options.fps, "video frames per second")
      ->capture_default_str()
      ->needs(video);
  view->add_option("--from", view_options.from_s, "video start, simulated s (default 0)")
      ->needs(video);
  view->add_option("--to", view_options.to_s, "video end, simulated s (default: the run's end)")
      ->needs(video);
  view->add_option("--size", view_options.size, "frame size WIDTHxHEIGHT in pixels")
      ->capture_default_str();
  view->add_option("--frame", view_options.frame_s, "draw the frame at T simulated s (with --png)");
  view->add_option("--png", view_options.png, "the frame's PNG file (with --frame)");
  view->add_flag("!--no-label", view_options.label, "leave the time label off frames and videos");
  view->add_flag("-q,--quiet", view_options.quiet, "print nothing but errors");

  std::string bench_out = "runs/bench/transport.json";
  double bench_min_time = 0.5;
  auto* bench = app.add_subcommand("bench", "performance benchmarks");
  bench->require_subcommand(1);
  auto* bench_transport = bench->add_subcommand(
      "transport", "ring, Unix socket and TCP side by side across two processes");
  bench_transport->add_option("--out", bench_out, "JSON results")->capture_default_str();
  bench_transport->add_option("--min-time", bench_min_time, "seconds per benchmark")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  std::vector<std::string> clean_dirs;
  auto* clean = app.add_subcommand(
      "clean", "remove the temporary files an interrupted run left in its run directories");
  clean->add_option("run_dir", clean_dirs, "run directory")
      ->required()
      ->check(CLI::ExistingDirectory);

  // Listed for help; its arguments go to the script untouched (plot.py has its own --help).
  app.add_subcommand("plot",
                     "draw a figure from a results.csv: mean and 95% CI over seeds per group "
                     "(runs scripts/plot.py with a python3 that has matplotlib; plot --help)");
  if (argc >= 2 && std::string(argv[1]) == "plot")
    return swarmnet::plot_command(std::vector<std::string>(argv + 2, argv + argc));

  if (argc == 2 && std::string(argv[1]) == "help") {
    std::cout << app.help();
    return 0;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // CLI11 quotes a refused value whole: a 100 KB argument would bury the message.
    if (error.get_exit_code() != 0 && std::string_view(error.what()).size() > kShownMessageChars) {
      std::fprintf(stderr, "%s\nRun with --help for more information.\n",
                   swarmnet::shown_value(error.what(), kShownMessageChars).c_str());
      return kExitBadInput;
    }
    return app.exit(error) == 0 ? 0 : kExitBadInput;
  }
  if (*run) return run_command(run_args, quiet, overwrite, run_view, transport);
  if (*view) return swarmnet::view_command(view_options);
  if (*clean) return clean_command(clean_dirs);
  if (*bench_transport) return swarmnet::bench_transport_command(bench_out, bench_min_time);
  if (*net) {
    net_options.step_timeout = std::chrono::milliseconds(std::llround(net_timeout_ms));
    net_options.out = net_out;
    net_options.plugin_paths.assign(net_plugin_paths.begin(), net_plugin_paths.end());
    if (net_max_memory->count() == 0) net_options.max_memory = swarmnet::default_memory_budget();
    net_options.handshake_timeout =
        std::chrono::milliseconds(std::llround(handshake_timeout_s * 1e3));
    if (!net_options.listen.empty()) swarmnet::install_stop_handlers();
    return swarmnet::run_network_process(net_options);
  }
  if (*validate) return validate_command(validate_args);
  if (*sweep) {
    sweep_options.file = sweep_file;
    sweep_options.out = sweep_out;
    if (const char* bin = std::getenv("SWARMNET_SLURM_BIN");
        sweep_swarmnet.empty() && bin != nullptr) {
      sweep_swarmnet = bin;
    }
    sweep_options.slurm.swarmnet = sweep_swarmnet;
    if (sweep_slurm) sweep_options.action = swarmnet::SweepAction::kSlurmSubmit;
    if (sweep_status) sweep_options.action = swarmnet::SweepAction::kStatus;
    if (sweep_collect) sweep_options.action = swarmnet::SweepAction::kCollect;
    return swarmnet::sweep_command(sweep_options);
  }
  if (*stats) {
    stats_options.file = stats_file;
    std::stringstream columns(stats_by);
    for (std::string name; std::getline(columns, name, ',');) {
      if (!name.empty()) stats_options.by.push_back(name);
    }
    return swarmnet::stats_command(stats_options, std::cout);
  }
  if (*replay) {
    replay_options.run_dir = replay_dir;
    replay_options.scenario = replay_scenario;
    replay_options.positions = replay_positions;
    replay_options.traffic = replay_traffic;
    replay_options.out = replay_out;
    return swarmnet::replay_command(replay_options);
  }
  if (*plugins) return plugins_command(plugin_name);
  return kExitBadInput;
}

int main(int argc, char** argv) {
  swarmnet::follow_parent_from_environment();
  try {
    return run_main(argc, argv);
  } catch (const std::exception& error) {
    // Every command handles its own errors; this is the last line against a crash.
    return fail(kExitRunFailed, error.what());
  }
}
