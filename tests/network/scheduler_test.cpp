#include "network/scheduler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "swarmnet/random.hpp"

namespace swarmnet {
namespace {

SimTime ns(std::int64_t n) { return SimTime{n}; }

TEST(NetworkScheduler, OrdersByTimeThenInsertion) {
  Scheduler scheduler;
  std::vector<int> order;
  scheduler.schedule_at(ns(30), [&] { order.push_back(1); });
  scheduler.schedule_at(ns(10), [&] { order.push_back(2); });
  scheduler.schedule_at(ns(20), [&] { order.push_back(3); });
  scheduler.schedule_at(ns(10), [&] { order.push_back(4); });
  scheduler.schedule_at(ns(10), [&] { order.push_back(5); });
  EXPECT_EQ(scheduler.run_until(ns(100)), 5U);
  EXPECT_EQ(order, (std::vector<int>{2, 4, 5, 3, 1}));
  EXPECT_EQ(scheduler.now(), ns(100));
}

TEST(NetworkScheduler, ClockIsTheEventTimeInsideCallbacks) {
  Scheduler scheduler;
  std::vector<SimTime> seen;
  scheduler.schedule_at(ns(7), [&] {
    seen.push_back(scheduler.now());
    scheduler.schedule_in(ns(5), [&] { seen.push_back(scheduler.now()); });
  });
  scheduler.run_until(ns(50));
  EXPECT_EQ(seen, (std::vector<SimTime>{ns(7), ns(12)}));
}

TEST(NetworkScheduler, EventsScheduledForNowRunAfterThoseAlreadyQueued) {
  Scheduler scheduler;
  std::vector<int> order;
  scheduler.schedule_at(ns(5), [&] {
    order.push_back(1);
    scheduler.schedule_in(ns(0), [&] { order.push_back(3); });
  });
  scheduler.schedule_at(ns(5), [&] { order.push_back(2); });
  scheduler.run_until(ns(6));
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
}

TEST(NetworkScheduler, CancelledEventsNeverRun) {
  Scheduler scheduler;
  std::vector<int> order;
  const TimerId a = scheduler.schedule_at(ns(10), [&] { order.push_back(1); });
  const TimerId b = scheduler.schedule_at(ns(20), [&] { order.push_back(2); });
  scheduler.schedule_at(ns(30), [&] { order.push_back(3); });
  EXPECT_TRUE(scheduler.pending(b));
  scheduler.cancel(b);
  EXPECT_FALSE(scheduler.pending(b));
  EXPECT_EQ(scheduler.pending_count(), 2U);
  EXPECT_EQ(scheduler.run_until(ns(100)), 2U);
  EXPECT_EQ(order, (std::vector<int>{1, 3}));
  // Cancelling fired, already cancelled, unknown and null ids does nothing.
  scheduler.cancel(a);
  scheduler.cancel(b);
  scheduler.cancel(kNoTimer);
  scheduler.cancel(0xdeadbeef12345ULL);
  EXPECT_EQ(scheduler.pending_count(), 0U);
}

TEST(NetworkScheduler, CancellingAFiredIdDoesNotHitTheTimerThatReusedItsSlot) {
  Scheduler scheduler;
  int ran = 0;
  const TimerId first = scheduler.schedule_at(ns(1), [&] { ++ran; });
  scheduler.run_until(ns(2));
  const TimerId second = scheduler.schedule_at(ns(3), [&] { ran += 10; });
  EXPECT_NE(first, second);
  EXPECT_EQ(scheduler.slot_capacity(), 1U);  // the slot was reused
  scheduler.cancel(first);
  EXPECT_TRUE(scheduler.pending(second));
  scheduler.run_until(ns(4));
  EXPECT_EQ(ran, 11);
}

TEST(NetworkScheduler, RunUntilExcludesTheEndInstant) {
  Scheduler scheduler;
  std::vector<int> order;
  scheduler.schedule_at(ns(99), [&] { order.push_back(1); });
  scheduler.schedule_at(ns(100), [&] { order.push_back(2); });
  EXPECT_EQ(scheduler.run_until(ns(100)), 1U);
  EXPECT_EQ(order, (std::vector<int>{1}));
  EXPECT_EQ(scheduler.now(), ns(100));
  EXPECT_EQ(scheduler.pending_count(), 1U);
  EXPECT_EQ(scheduler.run_until(ns(101)), 1U);
  EXPECT_EQ(order, (std::vector<int>{1, 2}));
  // An empty window still moves the clock.
  EXPECT_EQ(scheduler.run_until(ns(500)), 0U);
  EXPECT_EQ(scheduler.now(), ns(500));
}

TEST(NetworkScheduler, CancelFromInsideACallback) {
  Scheduler scheduler;
  std::vector<int> order;
  TimerId later = kNoTimer;
  TimerId same_instant = kNoTimer;
  TimerId self = kNoTimer;
  self = scheduler.schedule_at(ns(5), [&] {
    order.push_back(1);
    scheduler.cancel(self);  // its own, already firing: no effect
    scheduler.cancel(same_instant);
    scheduler.cancel(later);
  });
  same_instant = scheduler.schedule_at(ns(5), [&] { order.push_back(2); });
  later = scheduler.schedule_at(ns(10), [&] { order.push_back(3); });
  scheduler.schedule_at(ns(10), [&] { order.push_back(4); });
  EXPECT_EQ(scheduler.run_until(ns(20)), 2U);
  EXPECT_EQ(order, (std::vector<int>{1, 4}));
}

TEST(NetworkScheduler, SchedulingInThePastIsALogicError) {
  Scheduler scheduler;
  scheduler.run_until(ns(100));
  EXPECT_THROW(scheduler.schedule_at(ns(99), [] {}), std::logic_error);
  EXPECT_THROW(scheduler.schedule_in(ns(-1), [] {}), std::logic_error);
  EXPECT_THROW(scheduler.run_until(ns(50)), std::logic_error);
  EXPECT_NO_THROW(scheduler.schedule_at(ns(100), [] {}));
  EXPECT_EQ(scheduler.pending_count(), 1U);
}

TEST(NetworkScheduler, ManyRandomEventsComeOutSorted) {
  Scheduler scheduler;
  RandomStream random(42);
  struct Fired {
    SimTime time;
    std::size_t index;
  };
  std::vector<Fired> fired;
  std::vector<TimerId> ids;
  std::vector<SimTime> times;
  constexpr std::size_t kEvents = 100000;
  for (std::size_t i = 0; i < kEvents; ++i) {
    // Few distinct times, so that many events tie.
    const SimTime t = ns(static_cast<std::int64_t>(random.below(5000)));
    times.push_back(t);
    ids.push_back(scheduler.schedule_at(t, [&fired, &scheduler, i] {
      fired.push_back({scheduler.now(), i});
    }));
  }
  std::vector<bool> cancelled(kEvents, false);
  for (std::size_t i = 0; i < kEvents; ++i) {
    if (random.bernoulli(0.3)) {
      scheduler.cancel(ids[i]);
      cancelled[i] = true;
    }
  }
  const auto expected =
      static_cast<std::size_t>(std::count(cancelled.begin(), cancelled.end(), false));
  EXPECT_EQ(scheduler.run_until(ns(5000)), expected);
  ASSERT_EQ(fired.size(), expected);
  for (std::size_t k = 0; k < fired.size(); ++k) {
    EXPECT_FALSE(cancelled[fired[k].index]);
    EXPECT_EQ(fired[k].time, times[fired[k].index]);
    if (k > 0) {
      const bool ordered =
          fired[k - 1].time < fired[k].time ||
          (fired[k - 1].time == fired[k].time && fired[k - 1].index < fired[k].index);
      ASSERT_TRUE(ordered) << "event " << fired[k].index << " out of order";
    }
  }
  EXPECT_EQ(scheduler.pending_count(), 0U);
  EXPECT_EQ(scheduler.queue_size(), 0U);
}

TEST(NetworkScheduler, CancelledTimersDoNotAccumulate) {
  Scheduler scheduler;
  int ran = 0;
  // A protocol re-arming a far timeout over and over: one live timer at a time.
  TimerId timeout = kNoTimer;
  for (int i = 0; i < 100000; ++i) {
    scheduler.cancel(timeout);
    timeout = scheduler.schedule_in(ns(1'000'000'000), [&] { ++ran; });
    if (i % 100 == 0) scheduler.run_until(scheduler.now() + ns(1));
  }
  EXPECT_EQ(scheduler.pending_count(), 1U);
  EXPECT_LE(scheduler.queue_size(), 200U);
  EXPECT_LE(scheduler.slot_capacity(), 2U);
  scheduler.run_until(scheduler.now() + ns(2'000'000'000));
  EXPECT_EQ(ran, 1);
}

TEST(NetworkScheduler, CancellingReleasesTheCallbackAtOnce) {
  Scheduler scheduler;
  auto token = std::make_shared<int>(0);
  const TimerId id = scheduler.schedule_at(ns(10), [token] { ++*token; });
  EXPECT_EQ(token.use_count(), 2);
  scheduler.cancel(id);
  EXPECT_EQ(token.use_count(), 1);
}

TEST(NetworkScheduler, ClearDropsEverythingWithoutRunning) {
  Scheduler scheduler;
  auto token = std::make_shared<int>(0);
  const TimerId id = scheduler.schedule_at(ns(10), [token] { ++*token; });
  scheduler.schedule_at(ns(20), [token] { ++*token; });
  scheduler.clear();
  EXPECT_EQ(token.use_count(), 1);
  EXPECT_EQ(scheduler.pending_count(), 0U);
  const TimerId reused = scheduler.schedule_at(ns(30), [token] { ++*token; });
  EXPECT_FALSE(scheduler.pending(id));  // ids from before clear() stay dead
  EXPECT_TRUE(scheduler.pending(reused));
  scheduler.run_until(ns(100));
  EXPECT_EQ(*token, 1);
}

TEST(NetworkScheduler, ReservedSequencesRunWhereTheyWereReserved) {
  // Two events reserved first, scheduled last, still run before an event scheduled in between
  // for the same instant: the key is the reservation, not the call.
  Scheduler scheduler;
  std::vector<int> order;
  const std::uint64_t first = scheduler.reserve_sequences(2);
  scheduler.schedule_at(ns(10), [&] { order.push_back(3); });
  scheduler.schedule_reserved(ns(10), first + 1, [&] { order.push_back(2); });
  scheduler.schedule_reserved(ns(10), first, [&] { order.push_back(1); });
  scheduler.run_until(ns(11));
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
  EXPECT_THROW(scheduler.schedule_reserved(ns(20), first + 5, [] {}), std::logic_error);
}

TEST(NetworkScheduler, AdvanceIfNextOnlyWhenNothingComesFirst) {
  Scheduler scheduler;
  EXPECT_FALSE(scheduler.advance_if_next(ns(0), scheduler.reserve_sequences(1)));  // not running
  const std::uint64_t early = scheduler.reserve_sequences(1);
  scheduler.schedule_at(ns(20), [] {});
  const std::uint64_t late = scheduler.reserve_sequences(2);
  std::vector<bool> answers;
  std::vector<SimTime> clocks;
  scheduler.schedule_at(ns(5), [&] {
    answers.push_back(scheduler.advance_if_next(ns(20), late));   // after the pending event
    answers.push_back(scheduler.advance_if_next(ns(20), early));  // before it: runs now
    clocks.push_back(scheduler.now());
    answers.push_back(scheduler.advance_if_next(ns(10), late + 1));  // the clock never goes back
    answers.push_back(scheduler.advance_if_next(ns(60), late + 1));  // beyond the run's end
  });
  const std::uint64_t events_before = scheduler.events_run();
  EXPECT_EQ(scheduler.run_until(ns(50)), 3U);  // the 5 ns event, the advanced one, the 20 ns one
  EXPECT_EQ(scheduler.events_run() - events_before, 3U);
  EXPECT_EQ(answers, (std::vector<bool>{false, true, false, false}));
  EXPECT_EQ(clocks, (std::vector<SimTime>{ns(20)}));
}

TEST(NetworkScheduler, HasPassedComparesWithTheEventRunningNow) {
  Scheduler scheduler;
  const std::uint64_t reserved = scheduler.reserve_sequences(1);  // before the event below
  std::vector<bool> answers;
  scheduler.schedule_at(ns(10), [&] {
    answers.push_back(scheduler.has_passed(ns(10), reserved));      // same instant, earlier key
    answers.push_back(scheduler.has_passed(ns(10), reserved + 5));  // same instant, later key
    answers.push_back(scheduler.has_passed(ns(9), reserved + 5));
    answers.push_back(scheduler.has_passed(ns(11), 0));
  });
  scheduler.run_until(ns(10));
  EXPECT_TRUE(answers.empty());
  // Between runs the clock stands before every event at now().
  EXPECT_FALSE(scheduler.has_passed(ns(10), 0));
  EXPECT_TRUE(scheduler.has_passed(ns(9), reserved + 100));
  scheduler.run_until(ns(20));
  EXPECT_EQ(answers, (std::vector<bool>{true, false, true, false}));
}

// A stop signal must end even a window of millions of events: the loop asks every
// kEventsPerInterruptCheck events and throws between two of them.
std::atomic<bool> stop_now{false};
TEST(NetworkScheduler, AnInterruptCheckEndsAWindowBetweenTwoEvents) {
  Scheduler scheduler;
  scheduler.set_interrupt_check([] { return stop_now.load(); });
  std::uint64_t ran = 0;
  std::function<void()> tick = [&] {
    ++ran;
    if (ran == 5000) stop_now.store(true);
    scheduler.schedule_in(ns(1), [&] { tick(); });
  };
  scheduler.schedule_at(ns(0), [&] { tick(); });
  EXPECT_THROW(scheduler.run_until(ns(1'000'000'000)), SimulationInterrupted);
  // Asked at 4096 (false) and at 8192 events (true): not one event later than that.
  EXPECT_EQ(ran, 2 * Scheduler::kEventsPerInterruptCheck);
  stop_now.store(false);
  Scheduler unchecked;  // no check: the window runs to its end
  std::uint64_t count = 0;
  for (int i = 0; i < 10000; ++i) unchecked.schedule_at(ns(i), [&count] { ++count; });
  EXPECT_EQ(unchecked.run_until(ns(20000)), 10000U);
}

}  // namespace
}  // namespace swarmnet
