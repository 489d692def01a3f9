// cbr: constant-bit-rate traffic. A fixed fraction of the robots each sends fixed-size messages
// at a fixed rate to one destination.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/controller.hpp"

namespace swarmnet::cbr {

class Cbr final : public Controller {
 public:
  static PluginInfo info();
  explicit Cbr(const PluginArgs& args);

  void init(RobotContext& robot) override;
  void control_step(RobotContext& robot) override;
  void reset() override;

  // Metric names recorded for every message received from a CBR sender.
  static constexpr const char* kReceivedMetric = "cbr_received";  // delay, s
  static constexpr const char* kHopsMetric = "cbr_hops";          // links traversed

 private:
  [[nodiscard]] bool is_sender(RobotId robot) const {
    return robot < sender_flags_.size() && sender_flags_[robot] != 0;
  }
  void record_received(RobotContext& robot) const;

  // Parameters.
  double fraction_;
  double rate_hz_;
  std::uint32_t payload_bytes_;
  double start_s_;
  std::int64_t destination_param_;
  std::uint64_t seed_;
  std::uint64_t shared_seed_;
  RobotId self_;
  std::uint32_t robot_count_;

  // Fixed by init().
  std::vector<std::uint8_t> sender_flags_;  // indexed by robot id
  RobotId destination_ = kNoNode;           // kNoNode: this robot does not send
  double first_send_s_ = 0.0;
  std::vector<std::byte> payload_;

  // Running state: the next message's sequence number (reset() sets it back to 0).
  std::uint64_t sequence_ = 0;
};

}  // namespace swarmnet::cbr
