// event_memory: what one robot knows of the events (paper §VI-A: the fields of the messages plus
// the estimated number of robots that decided to go, from G and C messages).
//
// Ordered containers only, so that iteration (and so every decision) is deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>

#include "swarmnet/ids.hpp"
#include "swarmnet/vector.hpp"
#include "task_message.hpp"

namespace swarmnet::task_allocation {

struct KnownEvent {
  std::uint32_t id = 0;
  Vec2 position = Vec2::Zero();
  std::uint32_t required = 0;
  std::uint32_t skill = 0;
  std::uint32_t waiting = 0;
  // Robots believed to be going to the event, each with the memory's order stamp at the time
  // its decision was learnt (a later G after a C is a new decision, with a new stamp). The stamp
  // tells which robots decided before this robot did (see decision.hpp).
  std::map<RobotId, std::uint64_t> going;
  // Being serviced (H received or sent) or serviced: no longer a candidate.
  bool handled = false;

  bool operator==(const KnownEvent&) const = default;
};

class EventMemory {
 public:
  [[nodiscard]] const KnownEvent* find(std::uint32_t id) const;
  [[nodiscard]] bool contains(std::uint32_t id) const { return find(id) != nullptr; }
  [[nodiscard]] const std::map<std::uint32_t, KnownEvent>& events() const { return events_; }
  [[nodiscard]] std::size_t size() const { return events_.size(); }

  // Stores an event, or updates a known one's position, required robots, skill and waiting
  // count. Returns whether anything changed.
  bool upsert(std::uint32_t id, const Vec2& position, std::uint32_t required, std::uint32_t skill,
              std::uint32_t waiting);

  // Applies a message from robot `sender` (its originator). Every message carries the event's
  // fields, so a message about an unknown event stores it (with the message's waiting count).
  //   S: sets waiting, removes the sender from every going set (it now waits by the event); an S
  //      whose waiting count is below the required one reopens a handled event (its service
  //      stalled: a robot left or ran flat);
  //   G: adds the sender to the going set, and removes it from every other one (a robot goes to
  //      one event at a time, so a lost C does not leave it counted elsewhere);
  //   C: removes the sender from the going set;
  //   H: marks the event handled, removes the sender from every going set (it is there);
  //   A: sets waiting, removes the sender from every going set.
  // G, C and H leave the waiting count of a known event alone: only S and A are about it.
  // Returns whether the memory changed.
  bool apply(const TaskMessage& message, RobotId sender);

  // Adds `robot` to the event's going set (a no-op when it is there already); returns whether
  // it was added. The event must be known.
  bool add_going(std::uint32_t id, RobotId robot);
  bool remove_going(std::uint32_t id, RobotId robot);
  bool set_waiting(std::uint32_t id, std::uint32_t waiting);
  bool mark_handled(std::uint32_t id);
  // Clears the handled flag: the event needs robots again.
  bool reopen(std::uint32_t id);

  void clear() { *this = EventMemory{}; }

  bool operator==(const EventMemory&) const = default;

 private:
  KnownEvent* find_mutable(std::uint32_t id);
  // Removes `robot` from the going set of every event but `except` (none: every event).
  bool remove_going_elsewhere(RobotId robot, std::optional<std::uint32_t> except);

  std::map<std::uint32_t, KnownEvent> events_;
  std::uint64_t next_stamp_ = 0;
};

}  // namespace swarmnet::task_allocation
