// decision: the paper's rule on hand-built memories.
#include "decision.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

namespace swarmnet::task_allocation {
namespace {

constexpr RobotId kSelf = 10;

class TaskAllocationDecisionTest : public ::testing::Test {
 protected:
  std::optional<std::uint32_t> choose(double q = 0.0) {
    const DecisionInput input{&memory, kSelf, position, skills, &shunned, now, q};
    return decide(input, random);
  }

  EventMemory memory;
  Vec2 position = Vec2(0.0, 0.0);
  std::vector<std::uint32_t> skills{0};
  std::map<std::uint32_t, SimTime> shunned;
  SimTime now{};
  RandomStream random{42};
};

TEST_F(TaskAllocationDecisionTest, ClosestUnderServedEventFirst) {
  memory.upsert(1, Vec2(100.0, 0.0), 4, 0, 1);
  memory.upsert(2, Vec2(30.0, 40.0), 4, 0, 1);  // 50 m: closest
  memory.upsert(3, Vec2(0.0, 80.0), 4, 0, 1);
  EXPECT_EQ(choose(), 2U);
}

TEST_F(TaskAllocationDecisionTest, CoveredEventsAreSkipped) {
  memory.upsert(1, Vec2(100.0, 0.0), 4, 0, 1);
  memory.upsert(2, Vec2(10.0, 0.0), 4, 0, 2);
  memory.add_going(2, 3);
  memory.add_going(2, 4);  // waiting 2 + going 2 = required 4
  EXPECT_EQ(choose(), 1U);
  memory.upsert(2, Vec2(10.0, 0.0), 4, 0, 4);  // waiting alone covers it
  memory.remove_going(2, 3);
  memory.remove_going(2, 4);
  EXPECT_EQ(choose(), 1U);
}

TEST_F(TaskAllocationDecisionTest, SkillsHandledAndShunnedEventsAreNotCandidates) {
  memory.upsert(1, Vec2(10.0, 0.0), 4, 1, 0);  // skill 1: not ours
  memory.upsert(2, Vec2(20.0, 0.0), 4, 0, 0);
  memory.mark_handled(2);
  memory.upsert(3, Vec2(30.0, 0.0), 4, 0, 0);
  shunned[3] = from_seconds(50.0);
  memory.upsert(4, Vec2(40.0, 0.0), 4, 0, 0);
  EXPECT_EQ(choose(), 4U);
  now = from_seconds(50.0);  // the shunning is over
  EXPECT_EQ(choose(), 3U);
}

TEST_F(TaskAllocationDecisionTest, GoingAndCancelledFromOthersChangeTheDecision) {
  memory.upsert(1, Vec2(10.0, 0.0), 3, 0, 1);
  memory.upsert(2, Vec2(50.0, 0.0), 3, 0, 1);
  EXPECT_EQ(choose(), 1U);
  memory.apply(TaskMessage{MessageType::going, 1, Vec2(10.0, 0.0), 3, 0, 1, Vec2::Zero()}, 3);
  EXPECT_EQ(choose(), 1U);  // 1 waiting + 1 going < 3
  memory.apply(TaskMessage{MessageType::going, 1, Vec2(10.0, 0.0), 3, 0, 1, Vec2::Zero()}, 4);
  EXPECT_EQ(choose(), 2U);  // 1 + 2 covers 3
  memory.apply(TaskMessage{MessageType::cancelled, 1, Vec2(10.0, 0.0), 3, 0, 1, Vec2::Zero()}, 3);
  EXPECT_EQ(choose(), 1U);
}

TEST_F(TaskAllocationDecisionTest, WithoutCandidateAndQZeroItExplores) {
  memory.upsert(1, Vec2(10.0, 0.0), 2, 0, 2);
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(choose(0.0).has_value());
  EXPECT_EQ(choose(1.0), 1U);
  memory.clear();
  EXPECT_FALSE(choose(1.0).has_value());  // nothing known: explore
}

TEST_F(TaskAllocationDecisionTest, WithoutCandidateQPicksAnotherKnownEventUniformly) {
  memory.upsert(1, Vec2(10.0, 0.0), 2, 0, 2);
  memory.upsert(2, Vec2(20.0, 0.0), 2, 0, 2);
  memory.upsert(3, Vec2(30.0, 0.0), 2, 1, 0);  // other skill: never
  std::map<std::uint32_t, int> picks;
  int explored = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto choice = choose(0.5);
    if (choice) {
      ++picks[*choice];
    } else {
      ++explored;
    }
  }
  EXPECT_EQ(picks.count(3), 0U);
  EXPECT_NEAR(explored, 1000, 100);
  EXPECT_NEAR(picks[1], 500, 80);
  EXPECT_NEAR(picks[2], 500, 80);
  EXPECT_EQ(choose(1.0).has_value(), true);
}

TEST_F(TaskAllocationDecisionTest, OnItsOwnEventOnlyEarlierDecisionsCount) {
  // Needs 2 more; robots 3, self and 4 decided in that order.
  memory.upsert(1, Vec2(10.0, 0.0), 3, 0, 1);
  memory.add_going(1, 3);
  memory.add_going(1, kSelf);
  memory.add_going(1, 4);
  EXPECT_TRUE(under_served(*memory.find(1), kSelf));  // 1 + robot 3 < 3: stays
  EXPECT_FALSE(under_served(*memory.find(1), 4));     // 1 + robots 3, self: the last one leaves
  EXPECT_EQ(choose(), 1U);
  // Another robot not going counts everyone.
  EXPECT_FALSE(under_served(*memory.find(1), 99));
}

}  // namespace
}  // namespace swarmnet::task_allocation
