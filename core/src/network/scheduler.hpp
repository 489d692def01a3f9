// The network half's discrete-event engine: an integer-nanosecond clock and a queue of events.
//
// Events are ordered by (time, insertion sequence): two events at the same instant run in the
// order they were scheduled, so a run is a pure function of its inputs. Callbacks live in a slot
// vector recycled through a free list; the heap holds small (time, sequence, slot, generation)
// entries. Cancelling releases the slot (and the callback's captures) at once and leaves the heap
// entry behind as a tombstone that is skipped when it surfaces (lazy deletion); when tombstones
// outnumber live entries the heap is compacted, so cancelled timers never accumulate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "swarmnet/node_context.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class Scheduler {
 public:
  using Callback = std::function<void()>;

  Scheduler() = default;
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;
  Scheduler(Scheduler&&) = delete;
  Scheduler& operator=(Scheduler&&) = delete;
  ~Scheduler() = default;

  [[nodiscard]] SimTime now() const { return now_; }

  // Runs `callback` at `time` (>= now(); earlier is a logic error and throws std::logic_error).
  TimerId schedule_at(SimTime time, Callback callback);
  // Runs `callback` after `delay` (>= 0, else std::logic_error); saturates at kTimeNever.
  TimerId schedule_in(SimTime delay, Callback callback);
  // Cancels a pending event. A fired, cancelled, unknown or kNoTimer id is ignored.
  void cancel(TimerId timer);
  [[nodiscard]] bool pending(TimerId timer) const;

  // Runs every event with time < `end` (including those scheduled meanwhile), then sets the clock
  // to `end` (>= now(), else std::logic_error). Returns the number of events run.
  std::uint64_t run_until(SimTime end);

  // Drops every pending event without running it (the callbacks are destroyed now).
  void clear();

  [[nodiscard]] std::size_t pending_count() const { return live_; }
  [[nodiscard]] std::uint64_t events_run() const { return events_run_; }
  // Heap entries, tombstones included; bounded by about twice pending_count().
  [[nodiscard]] std::size_t queue_size() const { return heap_.size(); }
  // Callback slots ever allocated (reused through the free list).
  [[nodiscard]] std::size_t slot_capacity() const { return slots_.size(); }

 private:
  struct Slot {
    Callback callback;
    std::uint32_t generation = 1;  // bumped on release, so stale ids and entries do not match
    bool armed = false;
  };
  struct Entry {
    SimTime time;
    std::uint64_t sequence;
    std::uint32_t slot;
    std::uint32_t generation;
  };
  // std::push_heap builds a max-heap; "later" entries compare less so the earliest is on top.
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.time != b.time ? a.time > b.time : a.sequence > b.sequence;
    }
  };

  [[nodiscard]] bool is_live(const Entry& entry) const;
  void release(std::uint32_t slot);
  void compact();

  SimTime now_{kTimeZero};
  std::uint64_t next_sequence_ = 0;
  std::uint64_t events_run_ = 0;
  std::size_t live_ = 0;
  std::size_t tombstones_ = 0;
  std::vector<Entry> heap_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
};

}  // namespace swarmnet
