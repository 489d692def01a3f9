// The CPU time another process or thread has used: how a half tells a peer that is busy
// computing a long step from one that hangs (transport/wait_policy.hpp, WaitPolicy::peer_cpu).
// Liveness only: no value read here ever reaches a simulation result.
#pragma once

#include <pthread.h>
#include <sys/types.h>

#include <chrono>

namespace swarmnet {

// User plus system time of process `pid` (kept by the kernel in clock ticks, 10 ms on Linux),
// or 0 when the process cannot be read (it has exited, or /proc is not mounted).
std::chrono::nanoseconds process_cpu_time(pid_t pid);

// CPU time of `thread`, a thread of this process (its CPU clock), or 0 when it cannot be read
// (the thread has ended). `thread` must not have been joined yet.
std::chrono::nanoseconds thread_cpu_time(pthread_t thread);

}  // namespace swarmnet
