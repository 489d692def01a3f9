// Binary exponential backoff's contention window: CW starts at cw_min, becomes 2 (CW + 1) - 1
// (at most cw_max) after each failed attempt and returns to cw_min after a success or a drop; a
// backoff is uniform in [0, CW] slots.
#pragma once

#include <algorithm>
#include <cstdint>

#include "swarmnet/random.hpp"

namespace swarmnet::dcf80211 {

class ContentionWindow {
 public:
  ContentionWindow(std::uint32_t cw_min, std::uint32_t cw_max)
      : cw_min_(cw_min), cw_max_(std::max(cw_min, cw_max)), cw_(cw_min) {}

  void reset() { cw_ = cw_min_; }
  void failed() { cw_ = std::min(2 * (cw_ + 1) - 1, cw_max_); }
  [[nodiscard]] std::uint32_t value() const { return cw_; }
  [[nodiscard]] std::uint32_t draw(RandomStream& random) const {
    return static_cast<std::uint32_t>(random.below(std::uint64_t{cw_} + 1));
  }

 private:
  std::uint32_t cw_min_;
  std::uint32_t cw_max_;
  std::uint32_t cw_;
};

}  // namespace swarmnet::dcf80211
