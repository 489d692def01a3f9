// process_cpu_time (coupling/peer_cpu.hpp): how a half tells a busy peer from a hung one.
#include "coupling/peer_cpu.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <thread>

namespace swarmnet {
namespace {

void burn_cpu(std::chrono::milliseconds cpu) {
  const std::clock_t until =
      std::clock() + static_cast<std::clock_t>(cpu.count() * CLOCKS_PER_SEC / 1000);
  volatile double sink = 0.0;
  while (std::clock() < until) sink = sink + 1.0;
}

TEST(PeerCpu, AProcessThatComputesCountsTicksAndAStoppedOneDoesNot) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    for (;;) burn_cpu(std::chrono::milliseconds(100));
  }
  // A busy child's time grows (the kernel counts 10 ms ticks; allow a loaded machine time to
  // schedule it).
  const std::chrono::nanoseconds first = process_cpu_time(child);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (process_cpu_time(child) <= first && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_GT(process_cpu_time(child), first);
  // Stopped (as a hung peer is, for all the CPU it uses), it stands still.
  EXPECT_EQ(::kill(child, SIGSTOP), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::chrono::nanoseconds stopped = process_cpu_time(child);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(process_cpu_time(child), stopped);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  // Gone: nothing to read.
  EXPECT_EQ(process_cpu_time(child).count(), 0);
}

TEST(PeerCpu, ThisProcessReadsItsOwnTime) {
  burn_cpu(std::chrono::milliseconds(50));
  EXPECT_GT(process_cpu_time(::getpid()).count(), 0);
}

}  // namespace
}  // namespace swarmnet
