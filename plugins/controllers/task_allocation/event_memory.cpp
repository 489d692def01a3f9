#include "event_memory.hpp"

namespace swarmnet::task_allocation {

const KnownEvent* EventMemory::find(std::uint32_t id) const {
  const auto it = events_.find(id);
  return it == events_.end() ? nullptr : &it->second;
}

KnownEvent* EventMemory::find_mutable(std::uint32_t id) {
  const auto it = events_.find(id);
  return it == events_.end() ? nullptr : &it->second;
}

bool EventMemory::upsert(std::uint32_t id, const Vec2& position, std::uint32_t required,
                         std::uint32_t skill, std::uint32_t waiting) {
  KnownEvent* event = find_mutable(id);
  if (event == nullptr) {
    KnownEvent fresh;
    fresh.id = id;
    fresh.position = position;
    fresh.required = required;
    fresh.skill = skill;
    fresh.waiting = waiting;
    events_.emplace(id, std::move(fresh));
    return true;
  }
  const bool changed = event->position != position || event->required != required ||
                       event->skill != skill || event->waiting != waiting;
  event->position = position;
  event->required = required;
  event->skill = skill;
  event->waiting = waiting;
  return changed;
}

bool EventMemory::apply(const TaskMessage& message, RobotId sender) {
  const std::uint32_t id = message.event_id;
  bool changed = false;
  if (!contains(id)) {
    changed = upsert(id, message.event_position, message.required, message.skill, message.waiting);
  }
  switch (message.type) {
    case MessageType::status:
      changed |=
          upsert(id, message.event_position, message.required, message.skill, message.waiting);
      changed |= remove_going_elsewhere(sender, std::nullopt);
      if (message.waiting < message.required) changed |= reopen(id);
      break;
    case MessageType::abandoning:
      changed |=
          upsert(id, message.event_position, message.required, message.skill, message.waiting);
      changed |= remove_going_elsewhere(sender, std::nullopt);
      break;
    case MessageType::going:
      changed |= add_going(id, sender);
      changed |= remove_going_elsewhere(sender, id);
      break;
    case MessageType::cancelled:
      changed |= remove_going(id, sender);
      break;
    case MessageType::handling:
      changed |= mark_handled(id);
      changed |= remove_going_elsewhere(sender, std::nullopt);
      break;
  }
  return changed;
}

bool EventMemory::remove_going_elsewhere(RobotId robot, std::optional<std::uint32_t> except) {
  bool changed = false;
  for (auto& [id, event] : events_) {
    if (except && id == *except) continue;
    changed |= event.going.erase(robot) > 0;
  }
  return changed;
}

bool EventMemory::add_going(std::uint32_t id, RobotId robot) {
  KnownEvent* event = find_mutable(id);
  if (event == nullptr || event->going.contains(robot)) return false;
  event->going.emplace(robot, next_stamp_++);
  return true;
}

bool EventMemory::remove_going(std::uint32_t id, RobotId robot) {
  KnownEvent* event = find_mutable(id);
  return event != nullptr && event->going.erase(robot) > 0;
}

bool EventMemory::set_waiting(std::uint32_t id, std::uint32_t waiting) {
  KnownEvent* event = find_mutable(id);
  if (event == nullptr || event->waiting == waiting) return false;
  event->waiting = waiting;
  return true;
}

bool EventMemory::reopen(std::uint32_t id) {
  KnownEvent* event = find_mutable(id);
  if (event == nullptr || !event->handled) return false;
  event->handled = false;
  return true;
}

bool EventMemory::mark_handled(std::uint32_t id) {
  KnownEvent* event = find_mutable(id);
  if (event == nullptr || event->handled) return false;
  event->handled = true;
  return true;
}

}  // namespace swarmnet::task_allocation
