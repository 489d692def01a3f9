// task_allocation: the distributed task allocation of the RoboNetSim paper (§VI), over the
// task_events world.
//
// Robots explore a walled arena for events; an event needs `required` robots with its skill by
// it for a while. Robots coordinate with five broadcast messages (task_message.hpp): S status,
// G going, C cancelled going, H handling, A abandoning.
//
// World interface (the task_events world plugin's readings and requests):
//   "battery"        [fraction 0..1, low (1: go to the charger now)]
//   "skills"         the robot's skill ids, ascending
//   "events_in_view" per unserviced event within the discovery radius, ascending id:
//                    [id, x_m, y_m, skill, required, waiting]
//   "charger"        [x_m, y_m, radius_m]
//   "joined"         [] or [id, waiting, service_elapsed_s]
//   request "join" [id], request "leave" [].
//
// States: exploring, going(event), waiting(event), to_charger, charging. The full behaviour,
// with every choice where the paper is silent, is the description in info() (task_allocation.cpp);
// the units are event_memory (what a robot knows), decision (the paper's rule), explorer (the
// exploration with a memory of explored cells), steering (go-to-point with avoidance),
// world_view (the readings) and task_message (the wire format).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "encounter_watch.hpp"
#include "event_memory.hpp"
#include "explorer.hpp"
#include "steering.hpp"
#include "swarmnet/controller.hpp"
#include "swarmnet/random.hpp"
#include "task_message.hpp"
#include "world_view.hpp"

namespace swarmnet::task_allocation {

class TaskAllocation final : public Controller {
 public:
  enum class Mode : std::uint8_t { exploring, going, waiting, to_charger, charging };
  // "exploring", "going", ...: what the robot shows the viewer (RobotContext::show_state).
  [[nodiscard]] static const char* mode_name(Mode mode);

  static PluginInfo info();
  explicit TaskAllocation(const PluginArgs& args);

  void init(RobotContext& robot) override;
  void control_step(RobotContext& robot) override;
  void reset() override;

  // For tests: what the robot is doing and knows.
  [[nodiscard]] Mode mode() const { return state_.mode; }
  [[nodiscard]] std::optional<std::uint32_t> event() const;
  [[nodiscard]] const EventMemory& memory() const { return state_.memory; }
  [[nodiscard]] EventMemory& memory() { return state_.memory; }
  [[nodiscard]] const Explorer& explorer() const { return state_.explorer; }

 private:
  // Everything that changes while running, so that reset() can restore the post-init copy.
  struct State {
    RandomStream random;
    Mode mode = Mode::exploring;
    std::uint32_t event = 0;  // going or waiting: which
    SimTime waiting_since{};
    bool service_started = false;
    EventMemory memory;
    std::map<std::uint32_t, SimTime> shunned_until;  // abandoned events
    Explorer explorer;
    Steering steering;
    EncounterWatch encounters;  // reannounce_on_encounter
    SimTime next_beacon{};      // beacon_interval_s > 0
    SimTime next_reannounce{};  // reannounce_on_encounter: not before
  };

  bool receive(RobotContext& robot);
  // Stores and announces new events; returns whether any was new, and sets `chose` when the
  // robot decided to go to one.
  bool discover(RobotContext& robot, const std::vector<EventSighting>& in_view, bool& chose);
  void decide(RobotContext& robot);
  // Drops the abandoned events whose shun ended by `now`; returns whether any did, so that the
  // decision rule runs again (such an event is a candidate once more).
  bool forget_expired_shuns(SimTime now);
  void go_to(RobotContext& robot, std::uint32_t id);
  void explore(RobotContext& robot);
  void head_to_charger(RobotContext& robot, const std::optional<JoinStatus>& joined);
  void step_going(RobotContext& robot, const std::vector<EventSighting>& in_view);
  void step_waiting(RobotContext& robot, const std::optional<JoinStatus>& joined);
  void step_to_charger(RobotContext& robot);
  void step_charging(RobotContext& robot, const Battery& battery);
  void abandon(RobotContext& robot, const std::optional<JoinStatus>& joined);
  // The communication-aware additions, both off by default.
  void send_beacon(RobotContext& robot);
  void reannounce_on_encounter(RobotContext& robot);
  void broadcast(RobotContext& robot, MessageType type, std::uint32_t id,
                 std::uint32_t waiting) const;
  void broadcast(RobotContext& robot, MessageType type, std::uint32_t id) const;
  [[nodiscard]] bool has_skill(std::uint32_t skill) const;

  double other_event_probability_;
  SimTime abandon_after_;
  double arrive_radius_m_;
  double explore_cell_m_;
  double explore_scale_m_;
  double charge_until_;
  SimTime beacon_interval_;  // zero: no beacons
  bool reannounce_;
  SimTime reannounce_min_interval_;
  std::vector<std::uint32_t> skills_;  // read every step
  State state_;
  State initial_;
};

}  // namespace swarmnet::task_allocation
