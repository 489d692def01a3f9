// SDK test kit: a deterministic event scheduler for a plugin's unit tests, so that a MAC or a
// routing protocol runs in simulated time without the kernel. Events at one instant run in the
// order they were scheduled, as in the kernel's scheduler.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

#include "swarmnet/node_context.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::testing {

class TestScheduler {
 public:
  [[nodiscard]] SimTime now() const { return now_; }

  // Runs `callback` at now() + delay; delay must not be negative.
  TimerId schedule(SimTime delay, std::function<void()> callback) {
    if (delay < SimTime{0}) throw std::invalid_argument("TestScheduler: negative delay");
    const TimerId id = next_id_++;
    events_.emplace(Key{now_ + delay, id}, std::move(callback));
    return id;
  }

  // Cancels a pending event; a fired, cancelled or kNoTimer id is ignored.
  void cancel(TimerId id) {
    for (auto it = events_.begin(); it != events_.end(); ++it) {
      if (it->first.id == id) {
        events_.erase(it);
        return;
      }
    }
  }

  // Runs every event due at or before `end` (events they schedule included), then sets the
  // clock to `end`.
  void run_until(SimTime end) {
    while (!events_.empty() && events_.begin()->first.at <= end) {
      auto node = events_.extract(events_.begin());
      now_ = node.key().at;
      node.mapped()();
    }
    if (end > now_) now_ = end;
  }
  void run_for(SimTime duration) { run_until(now_ + duration); }

  // Runs events until none is left; returns how many ran. Stops with std::runtime_error after
  // `limit` events (a protocol that reschedules forever).
  std::uint64_t run_all(std::uint64_t limit = 10'000'000) {
    std::uint64_t ran = 0;
    while (!events_.empty()) {
      if (ran == limit) throw std::runtime_error("TestScheduler: event limit reached");
      auto node = events_.extract(events_.begin());
      now_ = node.key().at;
      node.mapped()();
      ++ran;
    }
    return ran;
  }

  [[nodiscard]] std::size_t pending() const { return events_.size(); }

 private:
  struct Key {
    SimTime at;
    TimerId id;  // increases with scheduling order: the tie-break
    bool operator<(const Key& other) const {
      return at != other.at ? at < other.at : id < other.id;
    }
  };
  SimTime now_{0};
  TimerId next_id_ = kNoTimer + 1;
  std::map<Key, std::function<void()>> events_;
};

}  // namespace swarmnet::testing
