#include "network/scheduler.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace swarmnet {

namespace {

constexpr std::size_t kArity = 4;
// Slots are numbered in 32 bits (TimerId keeps the slot + 1 in its low half).
constexpr std::size_t kMaxSlots = 0xffffffffU;

// A TimerId packs the slot (low 32 bits, +1 so that no id is kNoTimer) and the slot's generation
// (high 32 bits). A generation wraps after 2^32 reuses of one slot; an id kept that long could
// then match a newer timer, which no protocol timer lives long enough to meet.
TimerId make_id(std::uint32_t slot, std::uint32_t generation) {
  return (static_cast<std::uint64_t>(generation) << 32U) | (static_cast<std::uint64_t>(slot) + 1);
}

}  // namespace

TimerId Scheduler::schedule_at(SimTime time, Callback callback) {
  return push_event(time, next_sequence_++, std::move(callback));
}

std::uint64_t Scheduler::reserve_sequences(std::uint64_t count) {
  const std::uint64_t first = next_sequence_;
  next_sequence_ += count;
  return first;
}

TimerId Scheduler::schedule_reserved(SimTime time, std::uint64_t sequence, Callback callback) {
  if (sequence >= next_sequence_) {
    throw std::logic_error("Scheduler: sequence number " + std::to_string(sequence) +
                           " was not reserved");
  }
  return push_event(time, sequence, std::move(callback));
}

TimerId Scheduler::push_event(SimTime time, std::uint64_t sequence, Callback callback) {
  if (time < now_) {
    throw std::logic_error("Scheduler: event scheduled in the past (at " +
                           std::to_string(time.count()) + " ns, now " +
                           std::to_string(now_.count()) + " ns)");
  }
  const std::uint32_t slot = take_slot(std::move(callback));
  heap_push(Entry{time, sequence, slot, slots_[slot].generation});
  return make_id(slot, slots_[slot].generation);
}

std::uint32_t Scheduler::take_slot(Callback callback) {
  if (!callback) throw std::logic_error("Scheduler: empty callback");
  std::uint32_t slot = 0;
  if (free_slots_.empty()) {
    if (slots_.size() >= kMaxSlots) throw std::length_error("Scheduler: too many pending events");
    slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
  }
  Slot& s = slots_[slot];
  s.callback = std::move(callback);
  s.armed = true;
  ++live_;
  return slot;
}

TimerId Scheduler::schedule_in(SimTime delay, Callback callback) {
  if (delay < kTimeZero) {
    throw std::logic_error("Scheduler: negative delay (" + std::to_string(delay.count()) + " ns)");
  }
  const SimTime time = delay > kTimeNever - now_ ? kTimeNever : now_ + delay;
  return schedule_at(time, std::move(callback));
}

bool Scheduler::advance_if_next(SimTime time, std::uint64_t sequence) {
  if (!running_ || time < now_ || time >= run_end_ || sequence >= next_sequence_) return false;
  // A tombstone at the front may hide a later live event: then the answer is a conservative no.
  if (!heap_.empty() && !earlier(Entry{time, sequence, 0, 0}, heap_.front())) return false;
  now_ = time;
  current_sequence_ = sequence;
  ++events_run_;
  return true;
}

bool Scheduler::pending(TimerId timer) const {
  if (timer == kNoTimer) return false;
  const std::uint64_t slot = (timer & 0xffffffffULL) - 1;
  const auto generation = static_cast<std::uint32_t>(timer >> 32U);
  return slot < slots_.size() && slots_[slot].armed && slots_[slot].generation == generation;
}

void Scheduler::cancel(TimerId timer) {
  if (!pending(timer)) return;
  const auto slot = static_cast<std::uint32_t>((timer & 0xffffffffULL) - 1);
  release(slot);
  ++tombstones_;
  if (tombstones_ > 64 && tombstones_ * 2 > heap_.size()) compact();
}

std::uint64_t Scheduler::run_until(SimTime end) {
  if (end < now_) {
    throw std::logic_error("Scheduler: run_until(" + std::to_string(end.count()) +
                           " ns) is before now (" + std::to_string(now_.count()) + " ns)");
  }
  const std::uint64_t events_before = events_run_;
  run_end_ = end;
  running_ = true;
  // Cleared however the loop ends (a callback may throw).
  struct RunningFlag {
    bool& flag;
    ~RunningFlag() { flag = false; }
  } running_flag{running_};
  while (!heap_.empty() && heap_.front().time < end) {
    const Entry entry = heap_.front();
    heap_pop();
    if (!is_live(entry)) {
      --tombstones_;
      continue;
    }
    now_ = entry.time;
    current_sequence_ = entry.sequence;
    // Free the slot before running: the callback may schedule (reusing it) or cancel its own id.
    Callback callback = std::move(slots_[entry.slot].callback);
    release(entry.slot);
    ++events_run_;
    callback();
    if (interrupt_check_ != nullptr && events_run_ % kEventsPerInterruptCheck == 0 &&
        interrupt_check_()) {
      throw SimulationInterrupted("stopped at " + std::to_string(now_.count()) +
                                  " ns of simulated time, inside a window");
    }
  }
  now_ = end;
  return events_run_ - events_before;
}

void Scheduler::clear() {
  // Release every slot (bumping generations, so ids issued before stay dead), then destroy the
  // callbacks: a capture's destructor may call back into cancel(), which is then a no-op.
  std::vector<Callback> doomed;
  doomed.reserve(live_);
  for (std::uint32_t slot = 0; slot < slots_.size(); ++slot) {
    if (!slots_[slot].armed) continue;
    doomed.push_back(std::move(slots_[slot].callback));
    release(slot);
  }
  heap_.clear();
  tombstones_ = 0;
  doomed.clear();
}

bool Scheduler::is_live(const Entry& entry) const {
  const Slot& s = slots_[entry.slot];
  return s.armed && s.generation == entry.generation;
}

void Scheduler::release(std::uint32_t slot) {
  Slot& s = slots_[slot];
  s.callback.reset();
  s.armed = false;
  ++s.generation;
  free_slots_.push_back(slot);
  --live_;
}

void Scheduler::compact() {
  // Keys (time, sequence) are unique, so rebuilding the heap cannot change the order events pop.
  std::erase_if(heap_, [this](const Entry& entry) { return !is_live(entry); });
  for (std::size_t i = heap_.size() / kArity + 1; i-- > 0;) sift_down(i);
  tombstones_ = 0;
}

void Scheduler::heap_push(const Entry& entry) {
  heap_.push_back(entry);
  std::size_t index = heap_.size() - 1;
  while (index > 0) {
    const std::size_t parent = (index - 1) / kArity;
    if (!earlier(entry, heap_[parent])) break;
    heap_[index] = heap_[parent];
    index = parent;
  }
  heap_[index] = entry;
}

void Scheduler::heap_pop() {
  const Entry last = heap_.back();
  heap_.pop_back();
  if (heap_.empty()) return;
  heap_.front() = last;
  sift_down(0);
}

void Scheduler::sift_down(std::size_t index) {
  const std::size_t size = heap_.size();
  if (index >= size) return;
  const Entry entry = heap_[index];
  while (true) {
    const std::size_t first = index * kArity + 1;
    if (first >= size) break;
    const std::size_t last = std::min(first + kArity, size);
    std::size_t best = first;
    for (std::size_t child = first + 1; child < last; ++child) {
      if (earlier(heap_[child], heap_[best])) best = child;
    }
    if (!earlier(heap_[best], entry)) break;
    heap_[index] = heap_[best];
    index = best;
  }
  heap_[index] = entry;
}

}  // namespace swarmnet
