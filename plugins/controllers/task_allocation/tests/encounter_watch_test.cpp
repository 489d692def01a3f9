// EncounterWatch: a node in the table that the previous table did not hold is an encounter.
#include "encounter_watch.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarmnet::task_allocation {
namespace {

std::vector<RadioNeighbor> table(const std::vector<RobotId>& ids) {
  std::vector<RadioNeighbor> out;
  for (const RobotId id : ids) {
    RadioNeighbor n;
    n.id = id;
    out.push_back(n);
  }
  return out;
}

TEST(EncounterWatch, TheFirstNeighboursHeardAreAnEncounterAndAnEmptyTableIsNone) {
  EncounterWatch watch;
  EXPECT_FALSE(watch.met_someone(table({})));
  EXPECT_TRUE(watch.met_someone(table({4})));
}

TEST(EncounterWatch, TheSameOrFewerNeighboursAreNoEncounter) {
  EncounterWatch watch;
  EXPECT_TRUE(watch.met_someone(table({2, 7})));
  EXPECT_FALSE(watch.met_someone(table({2, 7})));
  EXPECT_FALSE(watch.met_someone(table({7})));
}

TEST(EncounterWatch, ANodeBackAfterLeavingTheTableIsMetAgain) {
  EncounterWatch watch;
  EXPECT_TRUE(watch.met_someone(table({2, 7})));
  EXPECT_FALSE(watch.met_someone(table({7})));
  EXPECT_TRUE(watch.met_someone(table({2, 7})));  // 2 aged out of the window, then was heard
  EXPECT_TRUE(watch.met_someone(table({1, 2, 7})));
}

}  // namespace
}  // namespace swarmnet::task_allocation
