// The CPU time another process has used, read from /proc: how a half tells a peer that is busy
// computing a long step from one that hangs (transport/wait_policy.hpp, WaitPolicy::peer_work).
// Liveness only: no value read here ever reaches a simulation result.
#pragma once

#include <sys/types.h>

#include <cstdint>

namespace swarmnet {

// User plus system time of process `pid` in clock ticks (sysconf(_SC_CLK_TCK) a second), or 0
// when the process cannot be read (it has exited, or /proc is not mounted).
std::uint64_t process_cpu_ticks(pid_t pid);

}  // namespace swarmnet
