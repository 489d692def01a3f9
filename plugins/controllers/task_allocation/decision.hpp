// decision: the paper's decision rule (§VI-A), a pure function of a robot's memory.
//
// Candidates are the known events that are not handled, need a skill the robot has, are not
// shunned (abandoned by this robot less than abandon_after_s ago) and are under-served:
//
//   required > waiting + (robots in the going set other than this robot)
//
// with one refinement, the paper's own words "the robots that *previously* decided to go there":
// for the event this robot is itself going to, only the robots whose decision it learnt before
// its own count (the memory's order stamps). Without it, k robots going to an event that needs
// k - 1 more would each see the others covering it and all of them would cancel; with it, the
// one that decided last leaves and the others stay. For any other event the whole going set
// counts, as the paper says.
//
// The closest candidate wins (ties: the lower event id). With no candidate, with probability
// other_event_probability the robot picks uniformly among the known, unhandled, unshunned events
// with its skill (over-served ones, then); otherwise it explores. The draw is made only when
// there is such an event to pick.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>

#include "event_memory.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::task_allocation {

struct DecisionInput {
  const EventMemory* memory = nullptr;
  RobotId self = 0;
  Vec2 position = Vec2::Zero();
  std::span<const std::uint32_t> skills;  // ascending
  // Events this robot abandoned, with the time until which it does not choose them again.
  const std::map<std::uint32_t, SimTime>* shunned_until = nullptr;
  SimTime now{};
  double other_event_probability = 0.0;
};

// Whether `event` still needs robots, seen from robot `self` (see the top of this file).
[[nodiscard]] bool under_served(const KnownEvent& event, RobotId self);

// The event to go to, or nothing to explore.
[[nodiscard]] std::optional<std::uint32_t> decide(const DecisionInput& input, RandomStream& random);

}  // namespace swarmnet::task_allocation
