// Process-shared futex wait/wake on a 32-bit word, for blocking on a ring that may live in
// shared memory (std::atomic::wait uses private futexes, which do not work across processes).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace swarmnet {

// Sleeps while *word == expected, at most `timeout`. Returns on a wake, a change of value, a
// signal or the timeout; callers re-check their condition.
void futex_wait(std::atomic<std::uint32_t>& word, std::uint32_t expected,
                std::chrono::nanoseconds timeout);
// Wakes every thread or process sleeping on `word`.
void futex_wake_all(std::atomic<std::uint32_t>& word);

}  // namespace swarmnet
