// The network half's discrete-event engine: an integer-nanosecond clock and a queue of events.
//
// Events are ordered by (time, insertion sequence): two events at the same instant run in the
// order they were scheduled, so a run is a pure function of its inputs. Callbacks live in a slot
// vector recycled through a free list; the heap holds small (time, sequence, slot, generation)
// entries. Cancelling releases the slot (and the callback's captures) at once and leaves the heap
// entry behind as a tombstone that is skipped when it surfaces (lazy deletion); when tombstones
// outnumber live entries the heap is compacted, so cancelled timers never accumulate.
//
// Reserved keys: a component may take an event's sequence number now and schedule (or never
// schedule) the event later at that key (reserve_sequences / schedule_reserved); it then runs
// exactly where it would have. The channel hands a frame to its receivers this way, and the PHY
// arms its preamble-detection timer only when the window's end can change anything.
//
// Cost (docs/performance.md): a frame's fan-out runs an event per receiver start and end, so
// the callback type stores captures of up to EventCallback::kInlineBytes inline (no allocation
// per event; a std::function handed in by a plugin fits as well), and the heap is 4-ary (half the
// depth of a binary heap, children of a node on one cache line).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "swarmnet/node_context.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

// A move-only `void()` callable. Callables of at most kInlineBytes (nothrow movable) live in the
// object itself; larger ones on the heap. Built from an empty std::function or nullptr it is
// empty.
class EventCallback {
 public:
  static constexpr std::size_t kInlineBytes = 48;

  EventCallback() noexcept = default;
  EventCallback(std::nullptr_t) noexcept {}  // NOLINT(google-explicit-constructor)
  template <typename F, typename D = std::decay_t<F>>
  requires(!std::is_same_v<D, EventCallback> && !std::is_same_v<D, std::nullptr_t> &&
           std::is_invocable_r_v<void, D&>)
      EventCallback(F&& f) {  // NOLINT(google-explicit-constructor)
    if constexpr (std::is_constructible_v<bool, const D&>) {
      if (!static_cast<bool>(f)) return;  // an empty std::function or a null function pointer
    }
    if constexpr (fits_inline<D>()) {
      ::new (static_cast<void*>(storage_)) D(std::forward<F>(f));
      ops_ = &kInlineOps<D>;
    } else {
      ::new (static_cast<void*>(storage_)) D*(new D(std::forward<F>(f)));
      ops_ = &kHeapOps<D>;
    }
  }
  EventCallback(EventCallback&& other) noexcept : ops_(other.ops_) {
    if (ops_ != nullptr) ops_->relocate(storage_, other.storage_);
    other.ops_ = nullptr;
  }
  EventCallback& operator=(EventCallback&& other) noexcept {
    if (this != &other) {
      reset();
      ops_ = other.ops_;
      if (ops_ != nullptr) ops_->relocate(storage_, other.storage_);
      other.ops_ = nullptr;
    }
    return *this;
  }
  EventCallback(const EventCallback&) = delete;
  EventCallback& operator=(const EventCallback&) = delete;
  ~EventCallback() { reset(); }

  void reset() noexcept {
    if (ops_ == nullptr) return;
    const Ops* ops = ops_;
    ops_ = nullptr;
    ops->destroy(storage_);
  }
  explicit operator bool() const noexcept { return ops_ != nullptr; }
  void operator()() { ops_->invoke(storage_); }

 private:
  struct Ops {
    void (*invoke)(void* storage);
    // Move-constructs into `to` from `from` and destroys `from`.
    void (*relocate)(void* to, void* from) noexcept;
    void (*destroy)(void* storage) noexcept;
  };
  template <typename D>
  static constexpr bool fits_inline() {
    return sizeof(D) <= kInlineBytes && alignof(D) <= alignof(std::max_align_t) &&
           std::is_nothrow_move_constructible_v<D>;
  }
  template <typename D>
  static constexpr Ops kInlineOps{[](void* s) { (*std::launder(static_cast<D*>(s)))(); },
                                  [](void* to, void* from) noexcept {
                                    D* source = std::launder(static_cast<D*>(from));
                                    ::new (to) D(std::move(*source));
                                    source->~D();
                                  },
                                  [](void* s) noexcept { std::launder(static_cast<D*>(s))->~D(); }};
  template <typename D>
  static constexpr Ops kHeapOps{
      [](void* s) { (**std::launder(static_cast<D**>(s)))(); },
      [](void* to, void* from) noexcept { ::new (to) D*(*std::launder(static_cast<D**>(from))); },
      [](void* s) noexcept { delete *std::launder(static_cast<D**>(s)); }};

  alignas(std::max_align_t) unsigned char storage_[kInlineBytes];
  const Ops* ops_ = nullptr;
};

// Where an event runs: its time, then the sequence number it was scheduled (or reserved) with.
struct EventKey {
  SimTime time{};
  std::uint64_t sequence = 0;
  friend bool operator<(const EventKey& a, const EventKey& b) {
    return a.time != b.time ? a.time < b.time : a.sequence < b.sequence;
  }
  friend bool operator==(const EventKey& a, const EventKey& b) = default;
};

// Thrown by Scheduler::run_until between two events when its interrupt check says stop.
class SimulationInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Scheduler {
 public:
  using Callback = EventCallback;
  // Asked every kEventsPerInterruptCheck events of a run_until (a relaxed load of a stop flag):
  // a window of millions of events still ends within milliseconds of a stop signal.
  using InterruptCheck = bool (*)();
  static constexpr std::uint64_t kEventsPerInterruptCheck = 4096;

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

  // Reserves `count` consecutive insertion sequence numbers and returns the first. An event later
  // scheduled with schedule_reserved(time, sequence, ...) runs exactly where an event scheduled
  // at `time` at the moment of the reservation would have run. The channel uses it to hand a
  // frame to its receivers one event at a time (a heap entry per frame, not per receiver)
  // without changing the order of anything.
  std::uint64_t reserve_sequences(std::uint64_t count);
  // Runs `callback` at `time` (>= now()) in the place of reserved sequence number `sequence`.
  // Each reserved number is used at most once; a number that was not reserved is a logic error.
  TimerId schedule_reserved(SimTime time, std::uint64_t sequence, Callback callback);
  // For the event running now, when it would otherwise schedule an event at (time, sequence), a
  // reserved key: if that event would run next (before every pending event, within the current
  // run_until), advances the clock to `time`, counts it as run and returns true; the caller then
  // does its work at once, saving a heap push and pop. Otherwise returns false and changes nothing.
  bool advance_if_next(SimTime time, std::uint64_t sequence);
  // Whether an event at key (time, sequence) would have run by now: before the event running now,
  // or, between runs, at a time before now(). A component that keeps a timer it has not armed (a
  // reserved key) asks this to know whether that moment has passed.
  [[nodiscard]] bool has_passed(SimTime time, std::uint64_t sequence) const {
    return earlier(Entry{time, sequence, 0, 0},
                   Entry{now_, running_ ? current_sequence_ : 0, 0, 0});
  }
  // The key of the moment now: the running event's, or between runs (now(), 0). Exactly the keys
  // before it have passed (has_passed).
  [[nodiscard]] EventKey current_key() const {
    return EventKey{now_, running_ ? current_sequence_ : 0};
  }
  // Cancels a pending event. A fired, cancelled, unknown or kNoTimer id is ignored.
  void cancel(TimerId timer);
  [[nodiscard]] bool pending(TimerId timer) const;

  // Runs every event with time < `end` (including those scheduled meanwhile), then sets the clock
  // to `end` (>= now(), else std::logic_error). Returns the number of events run.
  std::uint64_t run_until(SimTime end);
  // From now on, run_until throws SimulationInterrupted between two events once `check` returns
  // true (nullptr: never). The events already run stay run; the simulation is not resumable.
  void set_interrupt_check(InterruptCheck check) { interrupt_check_ = check; }

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
  static bool earlier(const Entry& a, const Entry& b) {
    return a.time != b.time ? a.time < b.time : a.sequence < b.sequence;
  }
  TimerId push_event(SimTime time, std::uint64_t sequence, Callback callback);
  std::uint32_t take_slot(Callback callback);
  [[nodiscard]] bool is_live(const Entry& entry) const;
  void release(std::uint32_t slot);
  void compact();
  // The 4-ary min-heap over heap_ (earliest first); keys are unique, so the order events pop in
  // does not depend on the heap's shape.
  void heap_push(const Entry& entry);
  void heap_pop();  // removes heap_.front()
  void sift_down(std::size_t index);

  InterruptCheck interrupt_check_ = nullptr;
  SimTime now_{kTimeZero};
  SimTime run_end_{kTimeZero};  // the bound of the run_until in progress
  bool running_ = false;
  std::uint64_t current_sequence_ = 0;  // of the event running now (while running_)
  std::uint64_t next_sequence_ = 0;
  std::uint64_t events_run_ = 0;
  std::size_t live_ = 0;
  std::size_t tombstones_ = 0;
  std::vector<Entry> heap_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
};

}  // namespace swarmnet
