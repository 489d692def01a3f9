#include "task_allocation.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "decision.hpp"

namespace swarmnet::task_allocation {

namespace {

constexpr double kChargeToleranceFraction = 1e-9;
constexpr std::uint64_t kBeaconOffsetStream = 0x42454143;  // "BEAC"

std::uint16_t to_u16(std::uint32_t value) {
  return static_cast<std::uint16_t>(std::min<std::uint32_t>(value, UINT16_MAX));
}

std::string metric(std::string_view prefix, MessageType type) {
  return std::string(prefix) + std::string(letter(type));
}

}  // namespace

PluginInfo TaskAllocation::info() {
  return PluginInfo{
      "task_allocation",
      "1.0.0",
      "Distributed task allocation with S/G/C/H/A broadcasts (RoboNetSim paper, section VI), over "
      "the task_events world.",
      "Each robot explores for events, announces them and decides, from what it has heard, "
      "whether to help at a known event or keep exploring. It uses the task_events world's "
      "readings battery, skills, events_in_view, charger and joined and its requests join and "
      "leave, and broadcasts five messages (flooded by the routing plugin): S status (a new "
      "event, or the robots now waiting by it), G going, C cancelled going, H handling (service "
      "started), A abandoning. Each carries the event's id, coordinates, robots required, skill "
      "and robots waiting, and the sender's coordinates, in a 43-byte little-endian record with "
      "a leading type byte; a payload of another size, an unknown type or a non-finite "
      "coordinate is ignored and counted as malformed_messages.\n"
      "Memory: per event, its fields, the set of robots believed to be going and a handled flag. "
      "G adds the sender to the event's going set and removes it from every other (a robot goes "
      "to one event at a time, so a lost C does not leave it counted elsewhere); C removes it; "
      "S, H and A remove it from every going set (it is at the event, or left it); S and A set "
      "the waiting count; H marks the event handled; an S whose waiting count is below the "
      "required one reopens a handled event (its service stalled). Any message about an unknown "
      "event stores it. Events within view also refresh the waiting count of a known event.\n"
      "States: exploring, going(event), waiting(event), to_charger, charging. Every step: the "
      "messages delivered are applied; a low battery sends the robot to the charger; every "
      "event in view not yet known is stored and announced with S, and an exploring robot with "
      "its skill goes to the closest such event that still needs robots (G); then, if the "
      "memory changed (a message, a discovery, a waiting count seen in view, or the end of an "
      "abandoned event's shun) and the robot is exploring or going, the decision rule runs once "
      "on the memory as it stands after all of the step's messages.\n"
      "Decision rule: candidates are the known, unhandled events with one of the robot's skills "
      "whose required count exceeds waiting plus the going robots other than this one; for the "
      "event the robot itself is going to, only those whose decision it learnt before its own "
      "count (the paper's 'previously decided'), so that k robots heading for an event that "
      "needs fewer do not all cancel at once. The closest candidate wins (ties: lower id). With "
      "none, with probability other_event_probability it picks uniformly among its known "
      "unhandled events with its skill, else it explores. A change of choice sends C for the "
      "old event and G for the new one. An event this robot abandoned is not chosen again for "
      "abandon_after_s. The rule also runs on leaving an event or the charger.\n"
      "Going: drive to the event; within arrive_radius_m, if the event is still in view, stop, "
      "request join and broadcast S with the waiting count read this step plus one (the reading "
      "was taken before this robot joined), or H instead when that count reaches the required "
      "one (this robot completes the group: one H per event), then wait; if it is no longer in "
      "view it was "
      "serviced meanwhile: it is marked handled, C is sent, the rule runs.\n"
      "Waiting: standing still. When 'joined' shows waiting >= required or a positive service "
      "time, the service has started: unless H was already sent or heard for the event, send H "
      "and mark it handled. If the count drops below the required one and the world's service "
      "clock restarts, the service stalled: send S with the count (reopening the event for the "
      "others) and wait again, abandon timer restarted. When 'joined' becomes empty the event was "
      "serviced (or the world dropped "
      "the join): it is marked handled and the robot explores. Without the service starting "
      "within abandon_after_s of arrival, the robot sends A (waiting less itself), requests "
      "leave and explores.\n"
      "Energy: when the battery reads low and the robot is not in a started service, it sends C "
      "if going, or A and leave if waiting, then drives to the charger, stops within half its "
      "radius (records charges) and stays until the fraction reaches charge_until and the low "
      "flag is off; pushed out of the radius, it drives back.\n"
      "Exploration (the paper's reference [24] is not given): the arena is cut into equal "
      "cells no larger than explore_cell_m; a cell is explored once the robot passed within "
      "explore_cell_m / 2 of its centre (whatever the robot was doing); the target is an "
      "unexplored cell's centre drawn with weight exp(-distance / explore_scale_m), redrawn "
      "when it is explored; cells whose centre is inside an obstacle never count; when all are "
      "explored the memory is cleared.\n"
      "Motion: go-to-point at max_speed_mps(), turning in place beyond 45 degrees of heading "
      "error, proportional steering otherwise; proximity below 0.5 m within 60 degrees of the "
      "heading makes it turn away (backing off below 0.25 m) and then drive 1 m straight.\n"
      "Communication awareness (off by default; the paper's controller has none): with "
      "beacon_interval_s > 0 every robot sends a one-hop beacon (one byte 'B', hop limit 1, "
      "first at a random offset within the interval, drawn from a stream of its own) so that "
      "robots with nothing to announce are heard; with reannounce_on_encounter (needs "
      "network.neighbors.enabled) a robot waiting by an event whose service has not started "
      "broadcasts S for it again, flooded, when its radio's neighbour table holds a robot the "
      "previous step's did not (it met someone who may not have heard), at most once per "
      "reannounce_min_interval_s.\n"
      "Metrics: sent.S .. sent.A and received.S .. received.A (one observation per message), "
      "decisions (one per run of the rule: 1 when its choice changed, else 0), abandoned, "
      "charges, malformed_messages, beacons, reannounced (S sent again on an encounter). Beacons "
      "received are not messages: they are neither counted nor malformed. Random draws come from "
      "the robot's own stream; reset() "
      "restores the state right after init().",
      {real_param("other_event_probability", 0.1, "",
                  "with no under-served event, probability to pick another known event with the "
                  "robot's skill rather than explore",
                  0.0, 1.0),
       real_param("abandon_after_s", 100.0, "s",
                  "a robot waiting this long without the service starting abandons the event "
                  "(and does not choose it again for as long)",
                  0.0),
       real_param("arrive_radius_m", 3.0, "m",
                  "distance to the event at which a going robot stops and joins; keep it below "
                  "the world's service radius",
                  1e-3),
       real_param("explore_cell_m", 50.0, "m",
                  "largest side of an exploration cell; a cell is explored within half of it", 1.0),
       real_param("explore_scale_m", 150.0, "m",
                  "distance scale of the exploration target draw, weight exp(-d / scale)", 1e-3),
       real_param("charge_until", 1.0, "",
                  "battery fraction at which a charging robot leaves the charger", 0.0, 1.0),
       real_param("beacon_interval_s", 0.0, "s",
                  "time between one-hop beacons; 0: none (the paper's controller)", 0.0),
       bool_param("reannounce_on_encounter", false,
                  "a robot waiting by an event that needs robots floods S again when it hears a "
                  "robot it did not hear at the previous step (needs network.neighbors.enabled, "
                  "and beacons for robots that are otherwise silent)"),
       real_param("reannounce_min_interval_s", 5.0, "s",
                  "least time between two such re-announcements by one robot", 0.0)}};
}

TaskAllocation::TaskAllocation(const PluginArgs& args)
    : other_event_probability_(args.params.real("other_event_probability")),
      abandon_after_(from_seconds(args.params.real("abandon_after_s"))),
      arrive_radius_m_(args.params.real("arrive_radius_m")),
      explore_cell_m_(args.params.real("explore_cell_m")),
      explore_scale_m_(args.params.real("explore_scale_m")),
      charge_until_(args.params.real("charge_until")),
      beacon_interval_(from_seconds(args.params.real("beacon_interval_s"))),
      reannounce_(args.params.boolean("reannounce_on_encounter")),
      reannounce_min_interval_(from_seconds(args.params.real("reannounce_min_interval_s"))) {
  state_.random = RandomStream(args.seed);
  if (beacon_interval_ > SimTime::zero()) {
    // Robots that all beaconed at the same instants would collide; a stream of its own leaves
    // the decision rule's draws as the paper's controller makes them.
    RandomStream offsets(derive_seed(args.seed, {kBeaconOffsetStream}));
    state_.next_beacon = from_seconds(offsets.uniform(0.0, to_seconds(beacon_interval_)));
  }
  initial_ = state_;
}

void TaskAllocation::init(RobotContext& robot) {
  state_.explorer = Explorer(robot.arena(), explore_cell_m_, explore_scale_m_);
  initial_ = state_;
}

void TaskAllocation::reset() { state_ = initial_; }

std::optional<std::uint32_t> TaskAllocation::event() const {
  if (state_.mode == Mode::going || state_.mode == Mode::waiting) return state_.event;
  return std::nullopt;
}

bool TaskAllocation::has_skill(std::uint32_t skill) const {
  return std::binary_search(skills_.begin(), skills_.end(), skill);
}

void TaskAllocation::broadcast(RobotContext& robot, MessageType type, std::uint32_t id,
                               std::uint32_t waiting) const {
  const KnownEvent* known = state_.memory.find(id);
  if (known == nullptr) return;
  TaskMessage message;
  message.type = type;
  message.event_id = id;
  message.event_position = known->position;
  message.required = to_u16(known->required);
  message.skill = to_u16(known->skill);
  message.waiting = to_u16(waiting);
  message.sender_position = robot.position();
  robot.send(kBroadcast, encode(message));
  robot.record(metric("sent.", type), 1.0);
}

void TaskAllocation::broadcast(RobotContext& robot, MessageType type, std::uint32_t id) const {
  const KnownEvent* known = state_.memory.find(id);
  if (known != nullptr) broadcast(robot, type, id, known->waiting);
}

const char* TaskAllocation::mode_name(Mode mode) {
  switch (mode) {
    case Mode::exploring:
      return "exploring";
    case Mode::going:
      return "going";
    case Mode::waiting:
      return "waiting";
    case Mode::to_charger:
      return "to_charger";
    case Mode::charging:
      return "charging";
  }
  return "unknown";
}

void TaskAllocation::control_step(RobotContext& robot) {
  skills_ = read_skills(robot);
  const Battery battery = read_battery(robot);
  const std::vector<EventSighting> in_view = read_events_in_view(robot);
  const std::optional<JoinStatus> joined = read_joined(robot);
  state_.explorer.observe(robot.position());

  bool changed = receive(robot);
  changed |= forget_expired_shuns(robot.now());

  const bool in_service = state_.mode == Mode::waiting && state_.service_started;
  if (battery.low && !in_service && state_.mode != Mode::to_charger &&
      state_.mode != Mode::charging) {
    head_to_charger(robot, joined);
  }

  bool chose = false;
  changed |= discover(robot, in_view, chose);
  if (changed && !chose) decide(robot);

  switch (state_.mode) {
    case Mode::exploring:
      explore(robot);
      break;
    case Mode::going:
      step_going(robot, in_view);
      break;
    case Mode::waiting:
      step_waiting(robot, joined);
      break;
    case Mode::to_charger:
      step_to_charger(robot);
      break;
    case Mode::charging:
      step_charging(robot, battery);
      break;
  }
  if (beacon_interval_ > SimTime::zero()) send_beacon(robot);
  if (reannounce_) reannounce_on_encounter(robot);
  robot.show_state(mode_name(state_.mode));
}

bool TaskAllocation::receive(RobotContext& robot) {
  bool changed = false;
  for (const ReceivedMessage& received : robot.inbox()) {
    if (received.source == robot.id()) continue;  // an echo of its own broadcast
    if (is_beacon(received.payload)) continue;    // heard, and so in the neighbour table
    const std::optional<TaskMessage> message = decode(received.payload);
    if (!message) {
      robot.record("malformed_messages", 1.0);
      continue;
    }
    robot.record(metric("received.", message->type), 1.0);
    changed |= state_.memory.apply(*message, received.source);
  }
  return changed;
}

bool TaskAllocation::discover(RobotContext& robot, const std::vector<EventSighting>& in_view,
                              bool& chose) {
  bool any = false;
  std::optional<std::uint32_t> closest;
  double closest_m = 0.0;
  for (const EventSighting& seen : in_view) {
    if (state_.memory.contains(seen.id)) {
      any |= state_.memory.set_waiting(seen.id, seen.waiting);
      continue;
    }
    any = true;
    state_.memory.upsert(seen.id, seen.position, seen.required, seen.skill, seen.waiting);
    broadcast(robot, MessageType::status, seen.id);
    const KnownEvent& known = *state_.memory.find(seen.id);
    const double distance_m = (seen.position - robot.position()).norm();
    if (has_skill(seen.skill) && under_served(known, robot.id()) &&
        (!closest || distance_m < closest_m)) {
      closest = seen.id;
      closest_m = distance_m;
    }
  }
  if (closest && state_.mode == Mode::exploring) {
    robot.record("decisions", 1.0);
    go_to(robot, *closest);
    chose = true;
  }
  return any;
}

bool TaskAllocation::forget_expired_shuns(SimTime now) {
  const std::size_t before = state_.shunned_until.size();
  std::erase_if(state_.shunned_until, [now](const auto& entry) { return now >= entry.second; });
  return state_.shunned_until.size() != before;
}

void TaskAllocation::go_to(RobotContext& robot, std::uint32_t id) {
  state_.memory.add_going(id, robot.id());
  broadcast(robot, MessageType::going, id);
  state_.mode = Mode::going;
  state_.event = id;
}

void TaskAllocation::decide(RobotContext& robot) {
  if (state_.mode != Mode::exploring && state_.mode != Mode::going) return;
  const std::optional<std::uint32_t> current =
      state_.mode == Mode::going ? std::optional<std::uint32_t>(state_.event) : std::nullopt;
  const DecisionInput input{&state_.memory,        robot.id(),  robot.position(),        skills_,
                            &state_.shunned_until, robot.now(), other_event_probability_};
  const std::optional<std::uint32_t> choice = task_allocation::decide(input, state_.random);
  robot.record("decisions", choice == current ? 0.0 : 1.0);
  if (choice == current) return;
  if (current) {
    broadcast(robot, MessageType::cancelled, *current);
    state_.memory.remove_going(*current, robot.id());
  }
  if (choice) {
    go_to(robot, *choice);
  } else {
    state_.mode = Mode::exploring;
  }
}

void TaskAllocation::explore(RobotContext& robot) {
  const Vec2 target = state_.explorer.target(robot.position(), state_.random);
  state_.steering.drive(robot, target);
}

void TaskAllocation::head_to_charger(RobotContext& robot, const std::optional<JoinStatus>& joined) {
  if (state_.mode == Mode::going) {
    broadcast(robot, MessageType::cancelled, state_.event);
    state_.memory.remove_going(state_.event, robot.id());
  }
  if (state_.mode == Mode::waiting) {
    const KnownEvent* known = state_.memory.find(state_.event);
    const std::uint32_t waiting = joined ? joined->waiting : (known ? known->waiting : 0U);
    const std::uint32_t others = waiting > 0 ? waiting - 1 : 0;
    state_.memory.set_waiting(state_.event, others);
    broadcast(robot, MessageType::abandoning, state_.event, others);
    robot.request("leave", {});
  }
  state_.mode = Mode::to_charger;
}

void TaskAllocation::step_going(RobotContext& robot, const std::vector<EventSighting>& in_view) {
  const KnownEvent* known = state_.memory.find(state_.event);
  if (known == nullptr) {  // cannot happen: events are never erased while running
    state_.mode = Mode::exploring;
    explore(robot);
    return;
  }
  if ((known->position - robot.position()).norm() > arrive_radius_m_) {
    state_.steering.drive(robot, known->position);
    return;
  }
  const auto seen = std::find_if(in_view.begin(), in_view.end(),
                                 [&](const EventSighting& e) { return e.id == state_.event; });
  if (seen == in_view.end() || !has_skill(seen->skill)) {
    // Serviced while this robot was on its way (or not an event it can join): give it up.
    broadcast(robot, MessageType::cancelled, state_.event);
    state_.memory.remove_going(state_.event, robot.id());
    state_.memory.mark_handled(state_.event);
    state_.mode = Mode::exploring;
    decide(robot);
    if (state_.mode == Mode::going) {
      step_going(robot, in_view);
    } else {
      explore(robot);
    }
    return;
  }
  Steering::stop(robot);
  const std::array<double, 1> args{static_cast<double>(state_.event)};
  robot.request("join", args);
  // The reading was taken before this robot joined: the world has not counted it yet.
  const std::uint32_t waiting = seen->waiting + 1;
  state_.memory.upsert(seen->id, seen->position, seen->required, seen->skill, waiting);
  state_.memory.remove_going(state_.event, robot.id());
  if (waiting >= seen->required) {
    // This robot completes the group: the service starts now, and it alone says so (H), so
    // that one H per event goes out, not one per participant.
    broadcast(robot, MessageType::handling, state_.event, waiting);
    state_.memory.mark_handled(state_.event);
  } else {
    broadcast(robot, MessageType::status, state_.event, waiting);
  }
  state_.mode = Mode::waiting;
  state_.waiting_since = robot.now();
  state_.service_started = false;
}

void TaskAllocation::step_waiting(RobotContext& robot, const std::optional<JoinStatus>& joined) {
  Steering::stop(robot);
  const std::uint32_t id = state_.event;
  if (!joined || joined->event != id) {
    // Serviced (the world clears the join and recharges the participants), or dropped by the
    // world: either way nothing is left to do here.
    state_.memory.mark_handled(id);
    state_.mode = Mode::exploring;
    state_.service_started = false;
    decide(robot);
    return;
  }
  state_.memory.set_waiting(id, joined->waiting);
  const KnownEvent* known = state_.memory.find(id);
  const std::uint32_t required = known != nullptr ? known->required : 0;
  if (!state_.service_started && (joined->waiting >= required || joined->service_elapsed_s > 0.0)) {
    state_.service_started = true;
    // Normally the robot that completed the group has sent H already (step_going); one that
    // came together otherwise (a robot back inside the radius) is announced here.
    if (known != nullptr && !known->handled) {
      broadcast(robot, MessageType::handling, id, joined->waiting);
      state_.memory.mark_handled(id);
    }
  } else if (state_.service_started && joined->waiting < required &&
             joined->service_elapsed_s == 0.0) {
    // The service stalled (a participant left or ran flat) and the world's clock restarted:
    // the event needs robots again. S with the waiting count reopens it for the others, and
    // this robot may abandon it again after abandon_after_s.
    state_.service_started = false;
    state_.waiting_since = robot.now();
    state_.memory.reopen(id);
    broadcast(robot, MessageType::status, id, joined->waiting);
  }
  if (!state_.service_started && robot.now() - state_.waiting_since > abandon_after_) {
    abandon(robot, joined);
  }
}

void TaskAllocation::abandon(RobotContext& robot, const std::optional<JoinStatus>& joined) {
  const std::uint32_t id = state_.event;
  const std::uint32_t others = joined && joined->waiting > 0 ? joined->waiting - 1 : 0;
  state_.memory.set_waiting(id, others);
  broadcast(robot, MessageType::abandoning, id, others);
  robot.request("leave", {});
  robot.record("abandoned", 1.0);
  state_.shunned_until[id] = robot.now() + abandon_after_;
  state_.mode = Mode::exploring;
  decide(robot);
}

void TaskAllocation::send_beacon(RobotContext& robot) {
  if (robot.now() < state_.next_beacon) return;
  state_.next_beacon += beacon_interval_;
  (void)robot.send(kBroadcast, encode_beacon(), SendOptions{1, false});
  robot.record("beacons", 1.0);
}

void TaskAllocation::reannounce_on_encounter(RobotContext& robot) {
  // Every step, so that the table compared with is the previous step's whatever the mode.
  const bool met = state_.encounters.met_someone(robot.neighbors());
  if (!met || state_.mode != Mode::waiting || state_.service_started ||
      robot.now() < state_.next_reannounce) {
    return;
  }
  const KnownEvent* known = state_.memory.find(state_.event);
  if (known == nullptr || known->handled) return;
  broadcast(robot, MessageType::status, state_.event);
  robot.record("reannounced", 1.0);
  state_.next_reannounce = robot.now() + reannounce_min_interval_;
}

void TaskAllocation::step_to_charger(RobotContext& robot) {
  const Charger charger = read_charger(robot);
  if ((charger.position - robot.position()).norm() <= 0.5 * charger.radius_m) {
    Steering::stop(robot);
    state_.mode = Mode::charging;
    robot.record("charges", 1.0);
    return;
  }
  state_.steering.drive(robot, charger.position);
}

void TaskAllocation::step_charging(RobotContext& robot, const Battery& battery) {
  Steering::stop(robot);
  const Charger charger = read_charger(robot);
  if ((charger.position - robot.position()).norm() > charger.radius_m) {
    state_.mode = Mode::to_charger;
    return;
  }
  if (battery.fraction >= charge_until_ - kChargeToleranceFraction && !battery.low) {
    state_.mode = Mode::exploring;
    decide(robot);
  }
}

}  // namespace swarmnet::task_allocation

SWARMNET_PLUGIN(swarmnet::task_allocation::TaskAllocation)
