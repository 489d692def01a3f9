// event_memory: how each of the five messages changes what a robot knows.
#include "event_memory.hpp"

#include <gtest/gtest.h>

namespace swarmnet::task_allocation {
namespace {

TaskMessage message(MessageType type, std::uint32_t id, std::uint16_t waiting = 1) {
  TaskMessage m;
  m.type = type;
  m.event_id = id;
  m.event_position = Vec2(10.0, 20.0);
  m.required = 4;
  m.skill = 1;
  m.waiting = waiting;
  m.sender_position = Vec2(1.0, 1.0);
  return m;
}

TEST(TaskAllocationMemoryTest, StatusStoresAnEventAndSetsWaiting) {
  EventMemory memory;
  EXPECT_TRUE(memory.apply(message(MessageType::status, 7, 1), 3));
  const KnownEvent* e = memory.find(7);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->position, Vec2(10.0, 20.0));
  EXPECT_EQ(e->required, 4U);
  EXPECT_EQ(e->skill, 1U);
  EXPECT_EQ(e->waiting, 1U);
  EXPECT_TRUE(e->going.empty());
  EXPECT_FALSE(e->handled);
  EXPECT_FALSE(memory.apply(message(MessageType::status, 7, 1), 3));  // nothing new
  EXPECT_TRUE(memory.apply(message(MessageType::status, 7, 2), 5));
  EXPECT_EQ(memory.find(7)->waiting, 2U);
}

TEST(TaskAllocationMemoryTest, GoingAndCancelledTrackTheSender) {
  EventMemory memory;
  memory.apply(message(MessageType::status, 7), 3);
  EXPECT_TRUE(memory.apply(message(MessageType::going, 7), 4));
  EXPECT_TRUE(memory.apply(message(MessageType::going, 7), 5));
  EXPECT_FALSE(memory.apply(message(MessageType::going, 7), 5));  // a copy
  EXPECT_EQ(memory.find(7)->going.size(), 2U);
  // G does not touch the waiting count of a known event.
  EXPECT_FALSE(memory.apply(message(MessageType::going, 7, 3), 5));
  EXPECT_EQ(memory.find(7)->waiting, 1U);
  EXPECT_TRUE(memory.apply(message(MessageType::cancelled, 7), 4));
  EXPECT_FALSE(memory.apply(message(MessageType::cancelled, 7), 4));
  EXPECT_EQ(memory.find(7)->going.count(5), 1U);
  EXPECT_EQ(memory.find(7)->going.count(4), 0U);
}

TEST(TaskAllocationMemoryTest, StatusOnArrivalMovesTheSenderFromGoingToWaiting) {
  EventMemory memory;
  memory.apply(message(MessageType::going, 7, 1), 4);  // G about an unknown event stores it
  ASSERT_TRUE(memory.contains(7));
  EXPECT_EQ(memory.find(7)->going.count(4), 1U);
  EXPECT_TRUE(memory.apply(message(MessageType::status, 7, 2), 4));
  EXPECT_EQ(memory.find(7)->going.count(4), 0U);
  EXPECT_EQ(memory.find(7)->waiting, 2U);
}

TEST(TaskAllocationMemoryTest, HandlingMarksAndAbandoningUpdatesWaiting) {
  EventMemory memory;
  memory.apply(message(MessageType::going, 7, 2), 4);
  EXPECT_TRUE(memory.apply(message(MessageType::abandoning, 7, 1), 4));
  EXPECT_EQ(memory.find(7)->waiting, 1U);
  EXPECT_TRUE(memory.find(7)->going.empty());
  EXPECT_TRUE(memory.apply(message(MessageType::handling, 7, 4), 6));
  EXPECT_TRUE(memory.find(7)->handled);
  EXPECT_FALSE(memory.apply(message(MessageType::handling, 7, 4), 8));
  // H about an unknown event stores it, handled.
  memory.apply(message(MessageType::handling, 9), 6);
  EXPECT_TRUE(memory.find(9)->handled);
}

TEST(TaskAllocationMemoryTest, LaterDecisionsGetLaterStamps) {
  EventMemory memory;
  memory.upsert(1, Vec2(0, 0), 4, 0, 0);
  memory.add_going(1, 9);
  memory.add_going(1, 2);
  EXPECT_LT(memory.find(1)->going.at(9), memory.find(1)->going.at(2));
  memory.remove_going(1, 9);
  memory.add_going(1, 9);  // a new decision, after robot 2's
  EXPECT_GT(memory.find(1)->going.at(9), memory.find(1)->going.at(2));
}

TEST(TaskAllocationMemoryTest, ARobotGoesToOneEventAtATime) {
  EventMemory memory;
  memory.apply(message(MessageType::status, 7), 3);
  memory.apply(message(MessageType::status, 8), 3);
  memory.apply(message(MessageType::going, 7), 4);
  // Its C for 7 was lost; its G for 8 says it left 7 anyway.
  EXPECT_TRUE(memory.apply(message(MessageType::going, 8), 4));
  EXPECT_FALSE(memory.find(7)->going.contains(4));
  EXPECT_TRUE(memory.find(8)->going.contains(4));
  // At an event (S, H) or gone (A): going nowhere.
  memory.apply(message(MessageType::status, 9, 1), 4);
  EXPECT_FALSE(memory.find(8)->going.contains(4));
  memory.apply(message(MessageType::going, 8), 6);
  memory.apply(message(MessageType::handling, 7, 4), 6);
  EXPECT_FALSE(memory.find(8)->going.contains(6));
}

TEST(TaskAllocationMemoryTest, AStatusShortOfRobotsReopensAHandledEvent) {
  EventMemory memory;
  memory.apply(message(MessageType::handling, 7, 4), 3);
  EXPECT_TRUE(memory.find(7)->handled);
  memory.apply(message(MessageType::status, 7, 4), 5);  // still enough there: still handled
  EXPECT_TRUE(memory.find(7)->handled);
  EXPECT_TRUE(memory.apply(message(MessageType::status, 7, 3), 3));  // the service stalled
  EXPECT_FALSE(memory.find(7)->handled);
  EXPECT_EQ(memory.find(7)->waiting, 3U);
}

}  // namespace
}  // namespace swarmnet::task_allocation
