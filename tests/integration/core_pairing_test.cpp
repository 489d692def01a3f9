// CorePairing keeps a strict run's two halves on one core and gives the robot half its CPU mask
// back afterwards. What the kernel does with the threads meanwhile is not asserted: only the
// masks, which the pairing sets.
#include "coupling/core_pairing.hpp"

#include <gtest/gtest.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <thread>

namespace swarmnet {
namespace {

int mask_count(pid_t thread, cpu_set_t& mask) {
  CPU_ZERO(&mask);
  return sched_getaffinity(thread, sizeof mask, &mask) == 0 ? CPU_COUNT(&mask) : -1;
}

TEST(CorePairing, PinsBothHalvesToOneCoreAndGivesTheMaskBack) {
  cpu_set_t before;
  if (mask_count(0, before) < 2) GTEST_SKIP() << "one usable CPU: nothing to pair";
  std::atomic<pid_t> network_tid{0};
  std::atomic<bool> done{false};
  std::thread network([&] {
    network_tid = static_cast<pid_t>(syscall(SYS_gettid));
    while (!done) std::this_thread::yield();
  });
  while (network_tid == 0) std::this_thread::yield();
  {
    CorePairing pairing({getpid(), network_tid});
    ASSERT_TRUE(pairing.pinned());
    cpu_set_t robot;
    cpu_set_t net;
    EXPECT_EQ(mask_count(0, robot), 1);
    EXPECT_EQ(mask_count(network_tid, net), 1);
    EXPECT_TRUE(CPU_EQUAL(&robot, &net)) << "the same core";
    EXPECT_TRUE(CorePairing::run_time({getpid(), network_tid}).has_value());
  }
  cpu_set_t after;
  mask_count(0, after);
  EXPECT_TRUE(CPU_EQUAL(&before, &after)) << "the robot half's mask is back";
  done = true;
  network.join();
}

TEST(CorePairing, WithoutALocalNetworkHalfNothingIsPinned) {
  cpu_set_t before;
  mask_count(0, before);
  {
    CorePairing pairing(ThreadId{});
    EXPECT_FALSE(pairing.pinned());
  }
  cpu_set_t after;
  mask_count(0, after);
  EXPECT_TRUE(CPU_EQUAL(&before, &after));
}

}  // namespace
}  // namespace swarmnet
