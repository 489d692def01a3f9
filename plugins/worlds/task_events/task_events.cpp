#include "task_events.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "event_placement.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::task_events {

PluginInfo TaskEvents::info() {
  return PluginInfo{
      "task_events",
      "1.0.0",
      "Events to service, skills, batteries and a charger: the RoboNetSim section VI world",
      "At setup, `events` events are placed uniformly at random in the arena shrunk by "
      "event_margin_m on each side (outside obstacles), each with a skill type drawn uniformly "
      "from skill_types; every robot gets skills_per_robot distinct skill types at random. Events "
      "and skills come from streams of their own, so a seed gives the same events whatever the "
      "swarm's size or communication model.\n"
      "Discovery: a robot sees (reading events_in_view) the unserviced events within "
      "discover_radius_m of it. Service: a robot asks to join an event (request join); a joined "
      "robot with the event's skill inside service_radius_m of it is waiting there. While at "
      "least required_robots are waiting, the event's service clock runs; when it drops below, "
      "the clock starts again from 0 (the robots must be there together for the whole time). "
      "After service_time_s (to within half a step) the event is serviced: every robot waiting "
      "there is recharged to a full battery (the reward), and the join of every robot that "
      "joined it ends.\n"
      "Energy: a full battery drives a robot for energy_s seconds at its maximum speed; driving "
      "a distance d costs d / (energy_s * max_speed) of it, and standing still costs nothing (the "
      "study's penalty on 'pointless moves'). Inside charger_radius_m of the arena's centre a "
      "robot charges at 1/charge_time_s per second (after paying for the step's driving). The "
      "battery reading's `low` flag is "
      "set below low_energy_fraction: the controller must then drive straight to the charger "
      "(the default 0.4 covers the 354 m from a corner of a 500 m arena at 5 m/s with room to "
      "spare). A robot whose battery is empty is switched off for the rest of the run.\n"
      "The run ends when the last event is serviced. Metrics: completion_time_s (once, when all "
      "are serviced), events_serviced (per event, its time), out_of_energy (per robot that ran "
      "flat, the time), distance_m (per robot, at the end), events_unserviced (once, at the end), "
      "infeasible_events (once, at setup: events whose skill fewer than required_robots robots "
      "have, which no run can service).",
      {integer_param("events", 10, "", "events to service", 1, 100000),
       integer_param("required_robots", 4, "robots", "robots with the skill an event needs (n)", 1,
                     100000),
       real_param("service_time_s", 50.0, "s", "time the robots must service an event together (t)",
                  0.0),
       integer_param("skill_types", 2, "", "number of skill (and event) types (ntypes)", 1, 64),
       integer_param("skills_per_robot", 1, "", "skills each robot has (nskills), <= skill_types",
                     1, 64),
       real_param("discover_radius_m", 50.0, "m", "a robot sees events this close (r_discover)",
                  0.0),
       real_param("service_radius_m", 10.0, "m",
                  "a joined robot this close to its event waits there", 0.0),
       real_param("energy_s", 200.0, "s", "driving time at full speed on a full battery (t_energy)",
                  1e-9),
       real_param("low_energy_fraction", 0.4, "",
                  "battery fraction below which the robot must go to the charger", 0.0, 1.0),
       real_param("charger_radius_m", 10.0, "m", "a robot this close to the centre charges", 0.0),
       real_param("charge_time_s", 20.0, "s", "time to charge an empty battery to full", 1e-9),
       real_param("event_margin_m", 25.0, "m", "no event is closer than this to a wall", 0.0)}};
}

TaskEvents::TaskEvents(const PluginArgs& args)
    : event_count_(static_cast<std::uint32_t>(args.params.integer("events"))),
      required_(static_cast<std::uint32_t>(args.params.integer("required_robots"))),
      service_time_s_(args.params.real("service_time_s")),
      skill_types_(static_cast<std::uint32_t>(args.params.integer("skill_types"))),
      skills_per_robot_(static_cast<std::uint32_t>(args.params.integer("skills_per_robot"))),
      discover_radius_m_(args.params.real("discover_radius_m")),
      service_radius_m_(args.params.real("service_radius_m")),
      energy_s_(args.params.real("energy_s")),
      low_energy_fraction_(args.params.real("low_energy_fraction")),
      charger_radius_m_(args.params.real("charger_radius_m")),
      charge_time_s_(args.params.real("charge_time_s")),
      event_margin_m_(args.params.real("event_margin_m")),
      seed_(args.seed) {
  if (skills_per_robot_ > skill_types_) {
    throw std::invalid_argument("skills_per_robot = " + std::to_string(skills_per_robot_) +
                                " is more than the " + std::to_string(skill_types_) +
                                " skill_types there are");
  }
}

std::vector<std::string> TaskEvents::readings() const {
  return {"battery", "skills", "events_in_view", "charger", "joined"};
}

std::vector<std::string> TaskEvents::requests() const { return {"join", "leave"}; }

void TaskEvents::setup(WorldContext& world) {
  const Arena& arena = world.arena();
  charger_ = Vec2(arena.width_m / 2.0, arena.height_m / 2.0);
  RandomStream event_random(derive_seed(seed_, {hash_name("events")}));
  events_ = place_events(arena, event_count_, event_margin_m_, skill_types_, event_random);
  remaining_ = event_count_;
  RandomStream skill_random(derive_seed(seed_, {hash_name("skills")}));
  const auto skills =
      draw_skills(world.robot_count(), skills_per_robot_, skill_types_, skill_random);
  robots_.assign(world.robot_count(), RobotState{});
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    robots_[r].skills = skills[r];
    robots_[r].last_position = world.position(static_cast<RobotId>(r));
  }
  // An event whose skill fewer than required_robots robots have can never be serviced: said
  // once, so that a run that cannot finish is told from one that did not.
  std::size_t infeasible = 0;
  for (const TaskEvent& event : events_) {
    const auto able = std::count_if(robots_.begin(), robots_.end(), [&](const RobotState& robot) {
      return has_skill(robot, event.skill);
    });
    if (static_cast<std::uint32_t>(able) < required_) ++infeasible;
  }
  world.record("infeasible_events", static_cast<double>(infeasible));
  show(world);
}

bool TaskEvents::has_skill(const RobotState& robot, std::uint32_t skill) const {
  return std::binary_search(robot.skills.begin(), robot.skills.end(), skill);
}

bool TaskEvents::at_charger(const Vec2& position) const {
  return (position - charger_).norm() <= charger_radius_m_;
}

void TaskEvents::post_step(WorldContext& world) {
  update_energy(world);
  update_events(world);
  show(world);
}

void TaskEvents::show(WorldContext& world) const {
  for (const TaskEvent& event : events_) {
    const char* state = event.serviced      ? "serviced"
                        : event.waiting > 0 ? "being serviced"
                                            : "unserviced";
    world.show_object(event.id, "event", state, event.position, service_radius_m_);
  }
  world.show_object(event_count_, "charger", "charger", charger_, charger_radius_m_);
}

void TaskEvents::update_energy(WorldContext& world) {
  const double step_s = world.step_s();
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    RobotState& robot = robots_[r];
    const auto id = static_cast<RobotId>(r);
    const Vec2 position = world.position(id);
    const double moved_m = (position - robot.last_position).norm();
    robot.last_position = position;
    robot.distance_m += moved_m;
    if (robot.flat) continue;
    robot.energy -= moved_m / (energy_s_ * world.max_speed_mps(id));
    if (robot.energy <= 0.0) {
      robot.energy = 0.0;
      robot.flat = true;
      robot.joined = kNoEvent;
      world.switch_off(id);
      world.record("out_of_energy", to_seconds(world.now()));
      continue;
    }
    if (at_charger(position)) robot.energy = std::min(1.0, robot.energy + step_s / charge_time_s_);
  }
}

void TaskEvents::update_events(WorldContext& world) {
  const double step_s = world.step_s();
  for (TaskEvent& event : events_) {
    if (event.serviced) continue;
    event.waiting = 0;
    for (const RobotState& robot : robots_) {
      if (robot.joined == event.id && !robot.flat &&
          (robot.last_position - event.position).norm() <= service_radius_m_) {
        ++event.waiting;
      }
    }
    event.service_elapsed_s = event.waiting >= required_ ? event.service_elapsed_s + step_s : 0.0;
    if (event.waiting < required_ || event.service_elapsed_s < service_time_s_ - 0.5 * step_s) {
      continue;
    }
    event.serviced = true;
    --remaining_;
    world.record("events_serviced", to_seconds(world.now()));
    for (RobotState& robot : robots_) {
      if (robot.joined != event.id) continue;
      if (!robot.flat && (robot.last_position - event.position).norm() <= service_radius_m_) {
        robot.energy = 1.0;
      }
      robot.joined = kNoEvent;
    }
    if (remaining_ == 0) world.record("completion_time_s", to_seconds(world.now()));
  }
}

void TaskEvents::end(WorldContext& world) {
  for (const RobotState& robot : robots_) world.record("distance_m", robot.distance_m);
  world.record("events_unserviced", static_cast<double>(remaining_));
}

void TaskEvents::read(const WorldContext& world, RobotId robot, std::string_view name,
                      std::vector<double>& out) const {
  const RobotState& state = robots_.at(robot);
  if (name == "battery") {
    out = {state.energy, state.energy < low_energy_fraction_ ? 1.0 : 0.0};
  } else if (name == "skills") {
    out.assign(state.skills.begin(), state.skills.end());
  } else if (name == "events_in_view") {
    const Vec2 position = world.position(robot);
    for (const TaskEvent& event : events_) {
      if (event.serviced || (event.position - position).norm() > discover_radius_m_) continue;
      out.insert(out.end(), {static_cast<double>(event.id), event.position.x(), event.position.y(),
                             static_cast<double>(event.skill), static_cast<double>(required_),
                             static_cast<double>(event.waiting)});
    }
  } else if (name == "charger") {
    out = {charger_.x(), charger_.y(), charger_radius_m_};
  } else if (name == "joined") {
    if (state.joined == kNoEvent) return;
    const TaskEvent& event = events_[state.joined];
    out = {static_cast<double>(event.id), static_cast<double>(event.waiting),
           event.service_elapsed_s};
  }
}

void TaskEvents::request(WorldContext& /*world*/, RobotId robot, std::string_view name,
                         std::span<const double> args) {
  RobotState& state = robots_.at(robot);
  if (name == "leave") {
    if (!args.empty()) throw std::invalid_argument("takes no arguments");
    state.joined = kNoEvent;
    return;
  }
  if (args.size() != 1 || !(args[0] >= 0.0) || args[0] >= static_cast<double>(events_.size()) ||
      args[0] != std::floor(args[0])) {
    throw std::invalid_argument("expects one argument, an event id from 0 to " +
                                std::to_string(events_.size() - 1));
  }
  const TaskEvent& event = events_[static_cast<std::size_t>(args[0])];
  if (!has_skill(state, event.skill)) {
    throw std::invalid_argument("event " + std::to_string(event.id) + " needs skill " +
                                std::to_string(event.skill) + ", which the robot lacks");
  }
  if (event.serviced || state.flat) return;
  state.joined = event.id;
}

}  // namespace swarmnet::task_events

SWARMNET_PLUGIN(swarmnet::task_events::TaskEvents)
