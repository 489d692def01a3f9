// The robot half's physics alone: one physics plugin, loaded from its shared object through the
// SDK's entry point as the kernel loads it, stepping N robots that diffuse at constant density.
// Prints one JSON object: CPU per simulated second, real-time factor, CPU per robot-step, split
// into step() and the proximity rings (sense_proximity()).
//
// Usage: physics_scaling PLUGIN_DIR ENGINE ROBOTS SIM_S [DENSITY_PER_M2] [SEED] [NAME=VALUE...]
// (NAME=VALUE: a plugin parameter other than its default.)
// The controller is a minimal diffusion (drive at 0.5 m/s, turn in place away from anything a
// front ray sees within 0.1 m, a random turn every ~10 s), written here so that its cost is
// negligible next to the physics and identical for both engines; it is not timed.
#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "swarmnet/physics.hpp"
#include "swarmnet/random.hpp"

namespace {

using swarmnet::Physics;
using swarmnet::RobotBody;

double cpu_now_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wall_now_s() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The plugin's library stays open for the life of the process (its objects are alive until exit).
std::unique_ptr<Physics> load(const std::string& dir, const std::string& name,
                              const std::vector<std::string>& overrides) {
  const std::string path = dir + "/swarmnet_" + name + ".so";
  void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) throw std::runtime_error(std::string("dlopen: ") + dlerror());
  using Entry = const swarmnet::SwarmnetPluginEntry* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(library, swarmnet::kPluginEntrySymbol));
  if (entry == nullptr) throw std::runtime_error(path + ": no entry symbol");
  const swarmnet::SwarmnetPluginEntry* e = entry();
  if (e->abi_version != swarmnet::kAbiVersion) throw std::runtime_error(path + ": ABI mismatch");
  const auto* descriptor = static_cast<const swarmnet::PluginDescriptor*>(e->descriptor);
  if (descriptor->kind != swarmnet::PluginKind::physics) {
    throw std::runtime_error(path + ": not a physics plugin");
  }
  swarmnet::PluginArgs args;
  for (const swarmnet::ParamSpec& spec : descriptor->info.params) {
    args.params.set(spec.name, spec.default_value);
  }
  for (const std::string& item : overrides) {
    const std::size_t equals = item.find('=');
    const std::string key = item.substr(0, equals);
    const std::string value = equals == std::string::npos ? "" : item.substr(equals + 1);
    bool known = false;
    for (const swarmnet::ParamSpec& spec : descriptor->info.params) {
      if (spec.name != key) continue;
      known = true;
      switch (spec.type) {
        case swarmnet::ParamType::real:
          args.params.set(key, std::stod(value));
          break;
        case swarmnet::ParamType::integer:
          args.params.set(key, static_cast<std::int64_t>(std::stoll(value)));
          break;
        case swarmnet::ParamType::boolean:
          args.params.set(key, value == "true");
          break;
        case swarmnet::ParamType::text:
          args.params.set(key, value);
          break;
      }
    }
    if (!known) throw std::runtime_error(name + " has no parameter " + key);
  }
  std::unique_ptr<swarmnet::Plugin> made = descriptor->create(args);
  return std::unique_ptr<Physics>(static_cast<Physics*>(made.release()));
}

struct Walker {
  int turning_steps = 0;  // > 0 turning left, < 0 right
  double next_random_turn_s = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s PLUGIN_DIR ENGINE ROBOTS SIM_S [DENSITY_PER_M2] [SEED]\n",
                 argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const std::string engine = argv[2];
  const auto robots = static_cast<std::size_t>(std::atol(argv[3]));
  const double sim_s = std::atof(argv[4]);
  const double density = argc > 5 ? std::atof(argv[5]) : 0.5;
  const std::uint64_t seed = argc > 6 ? std::strtoull(argv[6], nullptr, 10) : 1;
  constexpr double kStepS = 0.1;
  constexpr std::size_t kRays = 24;
  constexpr double kRangeM = 0.1;
  constexpr double kSpeedMps = 0.5;
  constexpr double kTurnMps = 0.2;

  // A square lattice of spacing 1/sqrt(density), each robot jittered inside its cell: no overlap,
  // O(N) placement, uniform density.
  const double spacing_m = 1.0 / std::sqrt(density);
  const auto per_row = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(robots))));
  const double side_m = spacing_m * static_cast<double>(per_row);
  swarmnet::Arena arena;
  arena.width_m = side_m;
  arena.height_m = side_m;
  swarmnet::RandomStream random(seed);
  std::vector<RobotBody> bodies(robots);
  const double jitter_m = 0.5 * spacing_m - 0.1;
  for (std::size_t i = 0; i < robots; ++i) {
    const double cx = spacing_m * (0.5 + static_cast<double>(i % per_row));
    const double cy = spacing_m * (0.5 + static_cast<double>(i / per_row));
    bodies[i].position = swarmnet::Vec2(cx + random.uniform(-jitter_m, jitter_m),
                                        cy + random.uniform(-jitter_m, jitter_m));
    bodies[i].heading_rad = random.uniform(-std::numbers::pi, std::numbers::pi);
    bodies[i].max_speed_mps = 1.0;
  }
  std::vector<Walker> walkers(robots);
  for (Walker& w : walkers) w.next_random_turn_s = 10.0 * -std::log(1.0 - random.uniform());

  std::vector<std::string> overrides;
  for (int a = 7; a < argc; ++a) overrides.emplace_back(argv[a]);
  std::unique_ptr<Physics> physics = load(dir, engine, overrides);
  physics->setup(arena, bodies);
  std::vector<double> rays(robots * kRays, kRangeM);

  const auto steps = static_cast<std::size_t>(std::llround(sim_s / kStepS));
  double step_cpu_s = 0.0;
  double sense_cpu_s = 0.0;
  const double wall_start_s = wall_now_s();
  for (std::size_t s = 0; s < steps; ++s) {
    const double now_s = static_cast<double>(s) * kStepS;
    for (std::size_t i = 0; i < robots; ++i) {
      Walker& w = walkers[i];
      const double* r = &rays[i * kRays];
      const double front_left = std::min({r[0], r[1], r[2]});
      const double front_right = std::min({r[0], r[kRays - 1], r[kRays - 2]});
      if (w.turning_steps == 0 && std::min(front_left, front_right) < kRangeM) {
        w.turning_steps = front_left < front_right ? -8 : 8;
      } else if (w.turning_steps == 0 && now_s >= w.next_random_turn_s) {
        w.turning_steps = random.bernoulli(0.5) ? 10 : -10;
        w.next_random_turn_s = now_s + 10.0 * -std::log(1.0 - random.uniform());
      }
      if (w.turning_steps != 0) {
        const double side = w.turning_steps > 0 ? 1.0 : -1.0;
        bodies[i].left_mps = -side * kTurnMps;
        bodies[i].right_mps = side * kTurnMps;
        w.turning_steps -= w.turning_steps > 0 ? 1 : -1;
      } else {
        bodies[i].left_mps = bodies[i].right_mps = kSpeedMps;
      }
    }
    const double t0 = cpu_now_s();
    physics->step(kStepS, bodies);
    const double t1 = cpu_now_s();
    for (std::size_t i = 0; i < robots; ++i) {
      physics->sense_proximity(bodies, i, kRangeM, std::span<double>(&rays[i * kRays], kRays));
    }
    const double t2 = cpu_now_s();
    step_cpu_s += t1 - t0;
    sense_cpu_s += t2 - t1;
  }
  const double wall_s = wall_now_s() - wall_start_s;
  const double cpu_s = step_cpu_s + sense_cpu_s;
  const double simulated_s = static_cast<double>(steps) * kStepS;
  const double robot_steps = static_cast<double>(steps) * static_cast<double>(robots);
  // Where the robots ended: a check that they moved, and a fingerprint of the run.
  double mean_x = 0.0;
  for (const RobotBody& b : bodies) mean_x += b.position.x() / static_cast<double>(robots);
  std::printf(
      "{\"engine\": \"%s\", \"robots\": %zu, \"arena_side_m\": %.3f, \"density_per_m2\": %.3f, "
      "\"sim_s\": %.1f, \"steps\": %zu, \"cpu_s\": %.4f, \"step_cpu_s\": %.4f, "
      "\"proximity_cpu_s\": %.4f, \"wall_s\": %.4f, \"cpu_s_per_sim_s\": %.5f, "
      "\"realtime_factor\": %.3f, \"us_per_robot_step\": %.3f, \"mean_x_m\": %.6f}\n",
      engine.c_str(), robots, side_m, density, simulated_s, steps, cpu_s, step_cpu_s, sense_cpu_s,
      wall_s, cpu_s / simulated_s, simulated_s / cpu_s, 1e6 * cpu_s / robot_steps, mean_x);
  return 0;
}
