// How much memory a network-half server (`swarmnet net --listen`) lets the runs it serves take.
// The kernel enforces it (RLIMIT_DATA: heap and private mappings), so a scenario that would need
// more fails with std::bad_alloc inside this process, which the server reports and survives,
// instead of the host's OOM killer taking whatever it picks.
#pragma once

#include <cstdint>
#include <string>

namespace swarmnet {

struct MemoryBudget {
  std::uint64_t bytes = 0;  // what the runs may use, above the server's own footprint
};

// Half the host's physical memory: a server that takes at most that leaves the host usable.
std::uint64_t default_memory_budget();

// Whether limit_process_memory() can work in this build: AddressSanitizer maps terabytes of
// shadow memory and aborts the process when an allocation fails, so under it the kernel's limit
// is not set (one step's payload bound still holds).
bool kernel_memory_limit_available();

// Sets this process's RLIMIT_DATA to what it uses now plus `budget.bytes` plus `reserve` (for
// the server's own threads' stacks). Throws RunError with the system's reason if it cannot.
// Does nothing where kernel_memory_limit_available() is false.
void limit_process_memory(const MemoryBudget& budget, std::uint64_t reserve);

// Bytes the heap holds for the program now (glibc's mallinfo2: in use, not free).
std::uint64_t heap_in_use_bytes();

// Gives free heap memory back to the system (malloc_trim) after a run; returns the resident
// set size afterwards, in bytes (from /proc/self/statm; 0 when unreadable).
std::uint64_t return_free_memory();

// "1.5 GiB", "320 MiB" for messages.
std::string describe_bytes(std::uint64_t bytes);

}  // namespace swarmnet
