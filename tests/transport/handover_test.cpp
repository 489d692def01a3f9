// The hand-over between two ends of a ring: how a wait chooses to spin, yield or sleep
// (WaitPace, spin conditions), and that every path hands each record over, between two threads
// and two processes, also when the peer shares this thread's core, dies while this end sleeps,
// or is stopped (SIGSTOP) and resumed. No assertion depends on how long anything takes.
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "spin_conditions.hpp"
#include "spsc_ring.hpp"
#include "transport_test_support.hpp"
#include "wait_pace.hpp"

namespace swarmnet {
namespace {

using std::chrono::microseconds;
using std::chrono::nanoseconds;
using test::pattern;
using test::quick_policy;

TEST(WaitPace, AQuickPeerIsWaitedForBySpinning) {
  const WaitPolicy policy = quick_policy();
  WaitPace pace;
  WaitPlan plan = pace.plan(policy, true);
  EXPECT_EQ(plan.spin_time, policy.spin_time) << "nothing learned yet: spin";
  EXPECT_EQ(plan.yield_iterations, policy.yield_iterations);
  for (int i = 0; i < 10; ++i) pace.record(microseconds(3), policy);
  plan = pace.plan(policy, true);
  EXPECT_EQ(plan.spin_time, policy.spin_time);
}

TEST(WaitPace, ALatePeerIsWaitedForBySleepingAtOnceWithAProbeNowAndThen) {
  const WaitPolicy policy = quick_policy();
  WaitPace pace;
  for (int i = 0; i < 20; ++i) pace.record(microseconds(200), policy);
  int spins = 0;
  for (std::uint32_t i = 1; i <= 3 * WaitPace::kProbeEvery; ++i) {
    const WaitPlan plan = pace.plan(policy, true);
    if (plan.spin_time.count() > 0) {
      ++spins;
      EXPECT_EQ(i % WaitPace::kProbeEvery, 0U) << "only every kProbeEvery-th wait probes";
    } else {
      EXPECT_EQ(plan.yield_iterations, 0U) << "a late peer on another core: no yields either";
    }
    pace.record(microseconds(200), policy);
  }
  EXPECT_EQ(spins, 3);
}

TEST(WaitPace, AProbeThatFindsThePeerQuickBringsTheSpinningBack) {
  const WaitPolicy policy = quick_policy();
  WaitPace pace;
  for (int i = 0; i < 20; ++i) pace.record(microseconds(500), policy);
  WaitPlan plan{};
  while ((plan = pace.plan(policy, true)).spin_time.count() == 0) {
    pace.record(microseconds(500), policy);
  }
  pace.record(microseconds(2), policy);  // the probe caught the answer within spin_worth
  EXPECT_EQ(pace.recent(), microseconds(2));
  EXPECT_EQ(pace.plan(policy, true).spin_time, policy.spin_time);
}

TEST(WaitPace, WhereSpinningCannotPayAWaitOnlyYields) {
  const WaitPolicy policy = quick_policy();
  WaitPace pace;
  const WaitPlan plan = pace.plan(policy, false);
  EXPECT_EQ(plan.spin_time, nanoseconds(0));
  EXPECT_EQ(plan.yield_iterations, policy.yield_iterations);
}

TEST(SpinConditions, SpinningPaysOnlyWithACoreToSpareForThePeer) {
  EXPECT_FALSE(spinning_pays_under({1, 1})) << "pinned to one CPU: the peer shares it";
  EXPECT_FALSE(spinning_pays_under({2, 3})) << "more runnable threads than CPUs";
  EXPECT_TRUE(spinning_pays_under({2, 2}));
  EXPECT_TRUE(spinning_pays_under({4, 0})) << "runnable threads unknown: the mask decides";
  const SpinConditions here = read_spin_conditions();
  EXPECT_GE(here.usable_cpus, 1);
}

// Two rings in shared anonymous memory, for threads or a fork()ed child.
struct RingPair {
  static constexpr std::uint64_t kCapacity = 4096;
  RingPair() : one(SpscRing::footprint(kCapacity)) {
    memory = mmap(nullptr, 2 * one, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) std::abort();
    SpscRing::create(there(), kCapacity);
    SpscRing::create(back(), kCapacity);
  }
  ~RingPair() { munmap(memory, 2 * one); }
  RingPair(const RingPair&) = delete;
  RingPair& operator=(const RingPair&) = delete;
  std::byte* there() { return static_cast<std::byte*>(memory); }
  std::byte* back() { return there() + one; }
  RingHeader& there_header() { return *reinterpret_cast<RingHeader*>(there()); }
  SpscRing attach(std::byte* where) {
    SpscRing ring;
    std::string error;
    if (!SpscRing::attach(where, one, ring, error)) std::abort();
    return ring;
  }
  std::size_t one;
  void* memory;
};

bool pin_to_cpu(pid_t thread, int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return sched_setaffinity(thread, sizeof set, &set) == 0;
}

// Echoes `rounds` tokens from `in` to `out`; false on the first failure.
bool echo(SpscRing in, SpscRing out, int rounds, const WaitPolicy& policy) {
  std::vector<std::byte> token;
  for (int i = 0; i < rounds; ++i) {
    if (in.pop(token, policy) != IoStatus::ok || out.push(token, policy) != IoStatus::ok) {
      return false;
    }
  }
  return true;
}

// Sends `rounds` tokens and counts those that came back unchanged.
int ping(SpscRing out, SpscRing in, int rounds, const WaitPolicy& policy) {
  std::vector<std::byte> token;
  int returned = 0;
  for (int i = 0; i < rounds; ++i) {
    const auto sent = pattern(24, static_cast<std::uint64_t>(i));
    if (out.push(sent, policy) != IoStatus::ok || in.pop(token, policy) != IoStatus::ok) break;
    returned += token == sent ? 1 : 0;
  }
  return returned;
}

// The echoing thread sleeps at once on every wait (a late peer as WaitPace would treat it),
// while this one waits by the default policy: every token comes back.
TEST(Handover, TwoThreadsOneSleepingAtOnceLoseNoWakeUp) {
  RingPair rings;
  WaitPolicy sleepy = quick_policy();
  sleepy.spin_time = nanoseconds(0);
  sleepy.yield_iterations = 0;
  constexpr int kRounds = 3000;
  std::atomic<bool> echoed{false};
  std::thread peer([&] {
    echoed = echo(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, sleepy);
  });
  EXPECT_EQ(ping(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, quick_policy()),
            kRounds);
  peer.join();
  EXPECT_TRUE(echoed);
}

// Both threads pinned to one CPU, as CorePairing keeps a strict run's halves: the waits yield
// and sleep instead of spinning, and every token comes back.
TEST(Handover, TwoThreadsOnOneCoreHandOverByYieldingAndSleeping) {
  RingPair rings;
  const int cpu = sched_getcpu();
  ASSERT_GE(cpu, 0);
  cpu_set_t before;
  ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
  ASSERT_TRUE(pin_to_cpu(0, cpu));
  EXPECT_FALSE(spinning_pays_under(read_spin_conditions()));
  constexpr int kRounds = 3000;
  std::atomic<bool> echoed{false};
  std::thread peer([&] {
    pin_to_cpu(0, cpu);
    echoed = echo(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, quick_policy());
  });
  EXPECT_EQ(ping(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, quick_policy()),
            kRounds);
  peer.join();
  EXPECT_TRUE(echoed);
  sched_setaffinity(0, sizeof before, &before);
}

// The same across two processes, the child on this process's core and then free.
TEST(Handover, TwoProcessesOnOneCoreAndApartLoseNoWakeUp) {
  for (const bool same_core : {true, false}) {
    RingPair rings;
    const int cpu = sched_getcpu();
    cpu_set_t before;
    ASSERT_EQ(sched_getaffinity(0, sizeof before, &before), 0);
    if (same_core) {
      ASSERT_TRUE(pin_to_cpu(0, cpu));
    }
    constexpr int kRounds = 3000;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      _exit(echo(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, quick_policy())
                ? 0
                : 4);
    }
    EXPECT_EQ(
        ping(rings.attach(rings.there()), rings.attach(rings.back()), kRounds, quick_policy()),
        kRounds)
        << (same_core ? "on one core" : "apart");
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    sched_setaffinity(0, sizeof before, &before);
  }
}

// Waits (without a timed step) until the consumer of `header`'s ring has gone to sleep.
void await_sleeper(const RingHeader& header) {
  while (header.consumer_sleeping.load() == 0) std::this_thread::yield();
}

TEST(Handover, APeerThatDiesWhileThisEndSleepsIsFound) {
  RingPair rings;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    for (;;) pause();  // never answers
  }
  std::atomic<bool> reaped{false};
  WaitPolicy policy = quick_policy();
  policy.peer_alive = [&] {
    if (!reaped && waitpid(child, nullptr, WNOHANG) == child) reaped = true;
    return !reaped;
  };
  std::thread killer([&] {
    await_sleeper(rings.there_header());
    kill(child, SIGKILL);
  });
  SpscRing in = rings.attach(rings.there());
  std::vector<std::byte> token;
  EXPECT_EQ(in.pop(token, policy), IoStatus::peer_dead);
  killer.join();
  if (!reaped) waitpid(child, nullptr, 0);
}

// The child waits for a go on one ring and answers on the other. It is stopped while this end
// sleeps waiting for the answer, sent the go while stopped, then resumed: the answer arrives.
TEST(Handover, APeerStoppedAndResumedStillAnswers) {
  RingPair rings;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    SpscRing go = rings.attach(rings.back());
    SpscRing answer = rings.attach(rings.there());
    std::vector<std::byte> token;
    if (go.pop(token, quick_policy()) != IoStatus::ok) _exit(3);
    _exit(answer.push(token, quick_policy()) == IoStatus::ok ? 0 : 4);
  }
  const auto sent = pattern(32, 9);
  std::thread controller([&] {
    SpscRing go = rings.attach(rings.back());
    await_sleeper(rings.there_header());
    kill(child, SIGSTOP);
    int status = 0;
    waitpid(child, &status, WUNTRACED);  // stopped for sure
    if (go.push(sent, quick_policy()) != IoStatus::ok) std::abort();
    kill(child, SIGCONT);
  });
  SpscRing answer = rings.attach(rings.there());
  std::vector<std::byte> token;
  EXPECT_EQ(answer.pop(token, quick_policy()), IoStatus::ok);
  EXPECT_EQ(token, sent);
  controller.join();
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

}  // namespace
}  // namespace swarmnet
