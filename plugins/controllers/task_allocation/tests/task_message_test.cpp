// task_message: the wire format round-trips and refuses what it cannot read.
#include "task_message.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace swarmnet::task_allocation {
namespace {

TaskMessage sample(MessageType type) {
  TaskMessage m;
  m.type = type;
  m.event_id = 0x01020304;
  m.event_position = Vec2(123.25, -7.5);
  m.required = 4;
  m.skill = 1;
  m.waiting = 3;
  m.sender_position = Vec2(499.875, 0.125);
  return m;
}

TEST(TaskAllocationMessageTest, EveryTypeRoundTrips) {
  for (const MessageType type : {MessageType::status, MessageType::going, MessageType::cancelled,
                                 MessageType::handling, MessageType::abandoning}) {
    const TaskMessage m = sample(type);
    const std::vector<std::byte> bytes = encode(m);
    ASSERT_EQ(bytes.size(), kTaskMessageBytes);
    const auto back = decode(bytes);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, m);
  }
}

TEST(TaskAllocationMessageTest, LayoutIsLittleEndianWithALeadingTypeByte) {
  const std::vector<std::byte> bytes = encode(sample(MessageType::going));
  EXPECT_EQ(bytes[0], std::byte{'G'});
  EXPECT_EQ(bytes[1], std::byte{0x04});  // event id, least significant byte first
  EXPECT_EQ(bytes[4], std::byte{0x01});
  EXPECT_EQ(bytes[21], std::byte{4});  // required
  EXPECT_EQ(bytes[22], std::byte{0});
  EXPECT_EQ(bytes[23], std::byte{1});  // skill
  EXPECT_EQ(bytes[25], std::byte{3});  // waiting
  // 123.25 = 0x405ED00000000000: its top byte last.
  EXPECT_EQ(bytes[12], std::byte{0x40});
  EXPECT_EQ(bytes[11], std::byte{0x5E});
  EXPECT_EQ(letter(MessageType::abandoning), "A");
}

TEST(TaskAllocationMessageTest, WrongSizesUnknownTypesAndNonFiniteCoordinatesAreRefused) {
  std::vector<std::byte> bytes = encode(sample(MessageType::status));
  std::vector<std::byte> longer = bytes;
  longer.push_back(std::byte{0});
  EXPECT_FALSE(decode(longer).has_value());
  EXPECT_FALSE(decode(std::span(bytes).first(kTaskMessageBytes - 1)).has_value());
  EXPECT_FALSE(decode({}).has_value());

  std::vector<std::byte> unknown = bytes;
  unknown[0] = std::byte{'X'};
  EXPECT_FALSE(decode(unknown).has_value());
  unknown[0] = std::byte{0};
  EXPECT_FALSE(decode(unknown).has_value());

  TaskMessage nan = sample(MessageType::status);
  nan.sender_position.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(decode(encode(nan)).has_value());
  TaskMessage inf = sample(MessageType::status);
  inf.event_position.y() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(decode(encode(inf)).has_value());
}

}  // namespace
}  // namespace swarmnet::task_allocation
