// libFuzzer target: the step protocol's records as a broken or hostile peer would send them.
// The input is cut into records (a 2-byte length, then the bytes), fed through an in-process
// channel, and read by both sides' decoders in turn. Every record must be decoded, refused with
// a message, or found out of place; nothing may crash or allocate beyond the bounds.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "inproc_channel.hpp"
#include "protocol/step_channel.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swarmnet;
  WaitPolicy policy;
  policy.timeout = std::chrono::milliseconds(1);  // input exhausted: the decoder times out
  InprocChannel link(std::uint64_t{1} << 20, policy);
  std::size_t at = 0;
  while (at + 2 <= size) {
    std::uint16_t length = 0;
    std::memcpy(&length, data + at, 2);
    at += 2;
    const std::size_t n = length <= size - at ? length : size - at;
    std::vector<std::byte> record(n);
    if (n > 0) std::memcpy(record.data(), data + at, n);
    at += n;
    if (link.robot_end().send(record) != IoStatus::ok) break;
    (void)link.network_end().send(record);
  }
  (void)link.robot_end().flush();
  (void)link.network_end().flush();
  link.robot_end().close();
  link.network_end().close();

  // The network half's view: a hello, then batches until finish or an error.
  StepChannel network(link.network_end(), "the robot half");
  // A hello, if the input starts with one; then batches, with the limits a welcome for a small
  // swarm fixes (as after the network half validated a scenario of 8 robots).
  const Welcome small{1, 8, 100'000'000};
  Hello hello;
  (void)network.receive_hello(hello);
  network.fix_limits(small);
  StepBatch batch;
  bool finished = false;
  for (int i = 0; i < 64 && network.receive_batch(batch, finished).ok() && !finished; ++i) {
  }
  // The robot half's view: a welcome, results, a report.
  StepChannel robot(link.robot_end(), "the network half");
  if (!robot.receive_welcome(small).ok()) robot.fix_limits(small);
  StepBatch owed;  // messages the robot half "sent", so that deliveries are accepted
  owed.positions.resize(8);
  for (std::uint64_t m = 0; m < 16; ++m) owed.messages.push_back({m, 0, kBroadcast, {}});
  (void)robot.send_batch(owed);
  StepResult result;
  for (int i = 0; i < 64 && robot.receive_result(result).ok(); ++i) {
  }
  NetworkReport report;
  (void)robot.receive_report(report);
  (void)robot.drain_for_failure();
  return 0;
}
