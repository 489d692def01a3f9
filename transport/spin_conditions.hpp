// Whether this thread's surroundings let a spinning wait pay at all. A spin helps only when the
// peer runs on another core meanwhile: not when this thread is pinned to one CPU (the robot half
// keeps a strict run's two halves on one core, core_pairing.hpp, and there a spin only keeps the
// peer off the core it waits for), and not when more threads are runnable than this thread may
// use CPUs (a sweep wider than the machine: spinning halves steal each other's cores).
#pragma once

#include <chrono>

namespace swarmnet {

// Re-reads this thread's CPU mask and the machine's runnable threads (/proc/loadavg) at most once
// per kSpinConditionsRefresh, so a wait pays for a system call or two only now and then. Only
// ever changes how long a wait spins, never what it returns.
[[nodiscard]] bool spinning_can_pay(std::chrono::steady_clock::time_point now);

inline constexpr std::chrono::milliseconds kSpinConditionsRefresh{20};

// The facts the answer comes from, for tests and benchmarks.
struct SpinConditions {
  int usable_cpus = 0;       // CPUs in this thread's affinity mask
  int runnable_threads = 0;  // runnable threads on the machine, this one included; 0: unknown
};
[[nodiscard]] SpinConditions read_spin_conditions();
[[nodiscard]] inline bool spinning_pays_under(const SpinConditions& c) {
  return c.usable_cpus > 1 && c.runnable_threads <= c.usable_cpus;
}

}  // namespace swarmnet
