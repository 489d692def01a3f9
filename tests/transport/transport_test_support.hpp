// What the transport tests share: reproducible payloads and a wait policy that gives up in time.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/random.hpp"
#include "wait_policy.hpp"

namespace swarmnet::test {

// `size` bytes drawn from `seed`: a payload whose every byte is checked on arrival.
inline std::vector<std::byte> pattern(std::size_t size, std::uint64_t seed) {
  std::vector<std::byte> bytes(size);
  RandomStream random(seed);
  for (auto& b : bytes) b = static_cast<std::byte>(random.next());
  return bytes;
}

// The default spin/yield/sleep policy with a timeout long enough for a loaded CI machine and
// short enough that a lost record fails the test instead of hanging it.
inline WaitPolicy quick_policy() {
  WaitPolicy policy;
  policy.timeout = std::chrono::seconds(20);
  return policy;
}

}  // namespace swarmnet::test
