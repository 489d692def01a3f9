// task_message: the five broadcast messages of the RoboNetSim task allocation (paper §VI-A) and
// their fixed-size little-endian wire format.
//
// Every message carries what the paper lists (event coordinates, robots required, required
// skill, robots waiting by the event, sender coordinates) plus the event's id, the label the
// world's "events_in_view" reading gives it. Layout, 43 bytes:
//
//   offset size field
//        0    1 type: 'S' status, 'G' going, 'C' cancelled going, 'H' handling, 'A' abandoning
//        1    4 event id (uint32)
//        5    8 event x, m (IEEE-754 binary64)
//       13    8 event y, m
//       21    2 robots required (uint16)
//       23    2 required skill (uint16)
//       25    2 robots waiting by the event (uint16)
//       27    8 sender x, m
//       35    8 sender y, m
//
// All integers and doubles little-endian, whatever the host. decode() refuses (returns nothing
// for) a payload of another size, an unknown type byte or a coordinate that is not finite.
//
// Not one of the paper's messages: with beacon_interval_s set, robots also send a one-hop
// beacon, the single byte 'B', so that their neighbours' radios hear robots that have nothing
// to announce (the encounter re-announcement, task_allocation.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "swarmnet/vector.hpp"

namespace swarmnet::task_allocation {

enum class MessageType : std::uint8_t {
  status = 'S',      // a discovered event, or the robots now waiting by it
  going = 'G',       // the sender decided to go to the event
  cancelled = 'C',   // the sender gave up going to the event
  handling = 'H',    // enough robots are by the event and its service started
  abandoning = 'A',  // the sender stopped waiting by the event
};

// The letter of the paper ("S", "G", ...), for metric names.
[[nodiscard]] std::string_view letter(MessageType type);

struct TaskMessage {
  MessageType type = MessageType::status;
  std::uint32_t event_id = 0;
  Vec2 event_position = Vec2::Zero();
  std::uint16_t required = 0;
  std::uint16_t skill = 0;
  std::uint16_t waiting = 0;
  Vec2 sender_position = Vec2::Zero();

  bool operator==(const TaskMessage&) const = default;
};

inline constexpr std::size_t kTaskMessageBytes = 43;

[[nodiscard]] std::vector<std::byte> encode(const TaskMessage& message);
[[nodiscard]] std::optional<TaskMessage> decode(std::span<const std::byte> payload);

[[nodiscard]] std::vector<std::byte> encode_beacon();
[[nodiscard]] bool is_beacon(std::span<const std::byte> payload);

}  // namespace swarmnet::task_allocation
