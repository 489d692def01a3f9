// How a `swarmnet` command ends, as its process's exit status (README, docs/scenario.md). A run
// stopped by a signal exits with 128 + the signal's number, as a shell reports it.
#pragma once

namespace swarmnet {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitRunFailed = 1;  // a run (or some run of a sweep) failed
inline constexpr int kExitBadInput = 2;   // usage, a scenario, a sweep file, a plugin, a column

}  // namespace swarmnet
