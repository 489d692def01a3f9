// How quickly the peer has lately answered one end's waits, learned so that a wait spins only
// when a spin is worth it. A spin costs the CPU it lasts; a sleep costs a futex wait, the peer's
// wake-up call and the switches (on the 2-core development VM about 16 µs of CPU when the
// sleeper's core is idle, docs/performance.md). So a wait whose peer lately answered within
// WaitPolicy::spin_worth spins; one whose peer takes longer (a network half waiting while the
// robot half computes its step) sleeps at once, and every kProbeEvery-th such wait spins anyway
// to notice a peer that has become quick. Only how a wait waits depends on this, never what it
// returns.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "spin_conditions.hpp"
#include "wait_policy.hpp"

namespace swarmnet {

class WaitPace {
 public:
  static constexpr std::uint32_t kProbeEvery = 16;

  // The spin and yields the next wait gets; `spinning_pays`: what spinning_can_pay() says now.
  // Where spinning cannot pay the yields stay, as they hand the core to a peer pinned to the
  // same one.
  [[nodiscard]] WaitPlan plan(const WaitPolicy& policy, bool spinning_pays) {
    probing_ = false;
    if (!spinning_pays) return {std::chrono::nanoseconds(0), policy.yield_iterations};
    if (recent_ <= policy.spin_worth) return {policy.spin_time, policy.yield_iterations};
    if (++late_waits_ % kProbeEvery != 0) return {std::chrono::nanoseconds(0), 0};
    probing_ = true;
    return {policy.spin_time, policy.yield_iterations};
  }

  // After a wait: how long after its start the answer came (a wait that slept also counts the
  // wake-up, so it reads as late).
  void record(std::chrono::nanoseconds answered_after, const WaitPolicy& policy) {
    // A probe that found the peer quick is believed at once; otherwise a moving average, so
    // that one slow step among quick ones does not stop the spinning.
    if (probing_ && answered_after <= policy.spin_worth) {
      recent_ = answered_after;
    } else {
      recent_ += (std::min(answered_after, kLongest) - recent_) / 4;
    }
  }

  [[nodiscard]] std::chrono::nanoseconds recent() const { return recent_; }

 private:
  static constexpr std::chrono::nanoseconds kLongest = std::chrono::milliseconds(1);
  std::chrono::nanoseconds recent_{0};
  std::uint32_t late_waits_ = 0;
  bool probing_ = false;
};

}  // namespace swarmnet
