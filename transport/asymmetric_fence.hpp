// Asymmetric memory fences between processes (Linux membarrier(2)).
//
// Waking a sleeper without losing a wake-up needs a store-then-load ordering on both sides: the
// waker stores "there is news" then loads "is anyone asleep?", the sleeper stores "I am asleep"
// then loads "is there news?". A full fence on every ring publish costs as much as the rest of
// the publish together. With asymmetric fences the frequent side (the waker) only stops the
// compiler from reordering (light_fence), and the rare side (a sleeper, after it has spun for
// tens of microseconds) pays for both with heavy_fence(), which makes every CPU running a
// registered process execute a full fence.
#pragma once

#include <atomic>

namespace swarmnet {

// Registers this process to receive heavy fences and says whether it may use both kinds: true
// on a Linux kernel with MEMBARRIER_CMD_GLOBAL_EXPEDITED (4.16 or later) that a seccomp filter
// does not hide. The first call per process does the registration (it survives fork() and is
// reset by exec(), so a fresh process registers when it first asks).
bool asymmetric_fences_available();

// The rare side's fence. Only after asymmetric_fences_available() returned true.
void heavy_fence();

// The frequent side's fence: ordered against heavy_fence() on other threads and processes,
// but only a compiler barrier here.
inline void light_fence() { std::atomic_signal_fence(std::memory_order_seq_cst); }

}  // namespace swarmnet
