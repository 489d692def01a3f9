// Channel scaling: network-half CPU time per simulated second at constant density.
//
// N robots, static, uniform in a square of side sqrt(N * 5000 m^2) (the reference study's 50
// robots in 500 x 500 m), 802.11a over log_distance with the sinr PHY and dcf80211, a 120 m
// nominal range (27.05 dBm), routing `direct`. Every node sends one 256-byte broadcast and one
// 256-byte unicast to a random node within 100 m per second, at random instants. Only the network
// half runs (no robot half, no transport): the CPU time of NetworkSimulator::run_step is measured
// with the process CPU clock. --sensing-floor-db sets network.phy.sensing_floor_db (quiet
// signals, network/phy.hpp; default: the settings default, exact).
//
//   channel_scaling [--nodes 50,200,800,3200] [--sim-s 10] [--no-cutoff] [--sensing-floor-db D]
//                   [--out results.json]
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "network/network_simulator.hpp"
#include "outputs/run_summary.hpp"
#include "plugin/default_plugin_choice.hpp"
#include "plugin/plugin_loader.hpp"
#include "swarmnet/random.hpp"

namespace {

using namespace swarmnet;

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

nlohmann::ordered_json run(PluginLoader& loader, std::uint32_t nodes, double sim_s, bool cutoff,
                           double sensing_floor_db) {
  NetworkSettings settings;
  settings.seed = 1;
  settings.step_s = 0.1;
  const double side = std::sqrt(nodes * 5000.0);
  settings.arena.width_m = side;
  settings.arena.height_m = side;
  settings.nodes = nodes;
  settings.network.propagation = {
      default_plugin_choice(loader, "log_distance", PluginKind::propagation)};
  settings.network.phy.model = PhyModel::sinr;
  settings.network.phy.tx_power_dbm = -82.0 + 46.6777 + 30.0 * std::log10(120.0);
  settings.network.phy.sensing_floor_db = sensing_floor_db;
  settings.network.channel.cutoff = cutoff;
  settings.network.mac = default_plugin_choice(loader, "dcf80211", PluginKind::mac);
  settings.network.routing = default_plugin_choice(loader, "direct", PluginKind::routing);

  RandomStream random(derive_seed(42, {nodes}));
  std::vector<Vec2> positions;
  for (std::uint32_t i = 0; i < nodes; ++i) {
    positions.emplace_back(random.uniform(0.0, side), random.uniform(0.0, side));
  }
  std::vector<std::vector<RobotId>> neighbours(nodes);
  for (std::uint32_t i = 0; i < nodes; ++i) {
    for (std::uint32_t j = 0; j < nodes; ++j) {
      if (i != j && (positions[i] - positions[j]).norm() <= 100.0) neighbours[i].push_back(j);
    }
  }

  NetworkSimulator simulator(settings, loader, nullptr);
  const auto steps = static_cast<std::uint64_t>(std::llround(sim_s / settings.step_s));
  const SimTime step = from_seconds(settings.step_s);
  std::uint64_t next_id = 0;
  double cpu = 0.0;
  StepResult result;
  for (std::uint64_t s = 0; s < steps; ++s) {
    StepBatch batch;
    batch.step = s;
    batch.start = step * static_cast<std::int64_t>(s);
    batch.positions = positions;
    // Rate 1/s each of broadcast and unicast: each node sends with probability 0.1 per step.
    for (std::uint32_t i = 0; i < nodes; ++i) {
      if (random.bernoulli(0.1)) {
        batch.messages.push_back(AppMessage{next_id++, i, kBroadcast, 0, Payload(256)});
      }
      if (!neighbours[i].empty() && random.bernoulli(0.1)) {
        const RobotId to = neighbours[i][random.below(neighbours[i].size())];
        batch.messages.push_back(AppMessage{next_id++, i, to, 0, Payload(256)});
      }
    }
    const double before = cpu_seconds();
    simulator.run_step(batch, result);
    cpu += cpu_seconds() - before;
  }
  const auto report = network_report_json(simulator.report());
  nlohmann::ordered_json row;
  row["nodes"] = nodes;
  row["side_m"] = side;
  row["cutoff"] = cutoff;
  row["cutoff_m"] = simulator.channel().cutoff_m();
  row["sensing_floor_db"] = sensing_floor_db;
  row["event_cutoff_m"] = simulator.channel().event_cutoff_m();
  row["sim_s"] = sim_s;
  row["cpu_s"] = cpu;
  row["cpu_per_sim_s"] = cpu / sim_s;
  row["cpu_per_sim_s_per_node_us"] = cpu / sim_s / nodes * 1e6;
  row["messages"] = report["packets"]["sent"];
  row["pdr"] = report["pdr"];
  row["tx_frames"] = report["mac"]["tx_frames"];
  row["events"] = report["events"];
  return row;
}

}  // namespace

static int run_benchmark(int argc, char** argv) {
  std::vector<std::uint32_t> sizes = {50, 200, 800, 3200};
  double sim_s = 10.0;
  bool cutoff = true;
  double sensing_floor_db = swarmnet::PhyConfig{}.sensing_floor_db;
  std::string out;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--nodes" && i + 1 < argc) {
      sizes.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
        sizes.push_back(static_cast<std::uint32_t>(std::stoul(item)));
    } else if (arg == "--sim-s" && i + 1 < argc) {
      sim_s = std::stod(argv[++i]);
    } else if (arg == "--no-cutoff") {
      cutoff = false;
    } else if (arg == "--sensing-floor-db" && i + 1 < argc) {
      sensing_floor_db = std::stod(argv[++i]);
    } else if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else {
      std::cerr << "usage: channel_scaling [--nodes 50,200,800,3200] [--sim-s 10] [--no-cutoff] "
                   "[--sensing-floor-db D] [--out results.json]\n";
      return 2;
    }
  }
  swarmnet::PluginLoader loader;
  nlohmann::ordered_json results;
  results["benchmark"] = "channel_scaling";
  results["results"] = nlohmann::ordered_json::array();
  for (const std::uint32_t n : sizes) {
    auto row = run(loader, n, sim_s, cutoff, sensing_floor_db);
    std::cerr << "N = " << n << ": " << row["cpu_per_sim_s"].get<double>()
              << " CPU-s per simulated s (" << row["tx_frames"] << " frames, pdr "
              << row["pdr"].get<double>() << ")\n";
    results["results"].push_back(std::move(row));
  }
  const std::string text = results.dump(2) + "\n";
  if (out.empty()) {
    std::cout << text;
  } else {
    std::ofstream(out) << text;
  }
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run_benchmark(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "channel_scaling: " << error.what() << "\n";
    return 1;
  }
}
