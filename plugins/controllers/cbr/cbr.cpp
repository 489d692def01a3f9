#include "cbr.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sender_selection.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::cbr {

namespace {

constexpr std::size_t kSequenceBytes = 8;

}  // namespace

PluginInfo Cbr::info() {
  return PluginInfo{
      "cbr",
      "1.0.0",
      "Constant-bit-rate traffic: a fraction of the robots each send fixed-size messages at a "
      "fixed rate to one destination.",
      "round(fraction * robots) robots (halves rounded up) are senders: the first ones of a "
      "Fisher-Yates shuffle of the robot ids drawn from the run's shared stream of this "
      "controller, so every robot agrees on the set and a different seed gives a different set. "
      "Each sender picks its destination once, uniformly among the other robots, from its own "
      "stream (or uses `destination` when it is set; that robot then never sends). Its first "
      "message leaves at start_s plus a random phase in [0, 1/rate_hz), so senders do not start "
      "in lockstep, then one every 1/rate_hz seconds. On each step it sends every message whose "
      "time has come (several per step when rate_hz exceeds 1/step_s), so the long-run rate is "
      "exact whatever the step.\n"
      "Payload: payload_bytes bytes, the first 8 holding the sender's sequence number (from 0, "
      "little-endian; fewer bytes hold its low bytes), the rest zero.\n"
      "Metrics: every robot records, for each message addressed to it (not broadcast) by a "
      "sender of this controller with the configured payload size, `cbr_received` = its delay "
      "(delivery minus send time, s) and `cbr_hops` = the links it traversed. Sends are counted "
      "by the kernel.",
      {real_param("fraction", 0.2, "", "fraction of the robots that send", 0.0, 1.0),
       real_param("rate_hz", 5.0, "1/s", "messages per second of each sender", 1e-3, 1e6),
       integer_param("payload_bytes", 512, "B", "application payload of each message", 1,
                     kMaxPayloadBytes),
       real_param("start_s", 1.0, "s", "no message is sent before this time", 0.0),
       integer_param("destination", -1, "",
                     "robot id every sender sends to, or -1 for a random destination per sender",
                     -1, static_cast<std::int64_t>(kNoNode) - 1)}};
}

Cbr::Cbr(const PluginArgs& args)
    : fraction_(args.params.real("fraction")),
      rate_hz_(args.params.real("rate_hz")),
      payload_bytes_(static_cast<std::uint32_t>(args.params.integer("payload_bytes"))),
      start_s_(args.params.real("start_s")),
      destination_param_(args.params.integer("destination")),
      seed_(args.seed),
      shared_seed_(args.shared_seed),
      self_(args.instance),
      robot_count_(args.instance_count) {}

void Cbr::init(RobotContext& robot) {
  self_ = robot.id();
  robot_count_ = static_cast<std::uint32_t>(robot.robot_count());
  const bool fixed = destination_param_ >= 0;
  if (fixed && destination_param_ >= static_cast<std::int64_t>(robot_count_)) {
    throw std::invalid_argument("cbr: destination " + std::to_string(destination_param_) +
                                " is not a robot id (there are " + std::to_string(robot_count_) +
                                " robots, ids 0.." + std::to_string(robot_count_ - 1) + ")");
  }
  const std::optional<RobotId> excluded =
      fixed ? std::optional<RobotId>(static_cast<RobotId>(destination_param_)) : std::nullopt;

  const std::uint32_t count = sender_count(fraction_, robot_count_, fixed);
  sender_flags_.assign(robot_count_, 0);
  for (const RobotId id : choose_senders(shared_seed_, robot_count_, count, excluded)) {
    sender_flags_[id] = 1;
  }

  destination_ = kNoNode;
  if (is_sender(self_)) {
    RandomStream random(seed_);
    if (fixed) {
      destination_ = static_cast<RobotId>(destination_param_);
    } else {
      // Uniform among the other robot_count - 1 robots.
      const auto pick = static_cast<RobotId>(random.below(robot_count_ - 1));
      destination_ = pick >= self_ ? pick + 1 : pick;
    }
    first_send_s_ = start_s_ + random.uniform() / rate_hz_;
    payload_.assign(payload_bytes_, std::byte{0});
  }
  sequence_ = 0;
}

void Cbr::reset() { sequence_ = 0; }

void Cbr::record_received(RobotContext& robot) const {
  for (const ReceivedMessage& message : robot.inbox()) {
    if (message.destination != self_ || !is_sender(message.source) ||
        message.payload.size() != payload_bytes_) {
      continue;
    }
    robot.record(kReceivedMetric, to_seconds(message.delivered_at - message.sent_at));
    robot.record(kHopsMetric, static_cast<double>(message.hops));
  }
}

void Cbr::control_step(RobotContext& robot) {
  record_received(robot);
  if (destination_ == kNoNode) return;
  const SimTime now = robot.now();
  // Message k is due at first_send_s_ + k / rate_hz_, computed afresh each time so that no
  // rounding accumulates over a long run.
  while (from_seconds(first_send_s_ + static_cast<double>(sequence_) / rate_hz_) <= now) {
    const std::size_t stamped = std::min(kSequenceBytes, payload_.size());
    for (std::size_t i = 0; i < stamped; ++i) {
      payload_[i] = static_cast<std::byte>((sequence_ >> (8U * i)) & 0xFFU);
    }
    robot.send(destination_, payload_);
    ++sequence_;
  }
}

}  // namespace swarmnet::cbr

SWARMNET_PLUGIN(swarmnet::cbr::Cbr)
