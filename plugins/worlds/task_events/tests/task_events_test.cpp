// task_events on a fake world (SDK test kit): discovery, service, energy, the end of the task.
#include "task_events.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "swarmnet/testing.hpp"

namespace swarmnet::task_events {
namespace {

using testing::FakeWorldContext;
using testing::ParamOverrides;
using testing::plugin_args;

const Arena kArena{500.0, 500.0, {}};

struct Fixture {
  std::unique_ptr<TaskEvents> plugin;
  FakeWorldContext world;
};

Fixture make(std::size_t robots, const ParamOverrides& overrides, std::uint64_t seed = 7) {
  Fixture s{std::make_unique<TaskEvents>(plugin_args<TaskEvents>(overrides, seed)),
            FakeWorldContext(robots, kArena)};
  s.world.max_speeds.assign(robots, 5.0);
  // Far from the charger at the centre (250, 250), so that no robot charges unless a test says.
  s.world.positions.assign(robots, Vec2(5.0, 5.0));
  s.plugin->setup(s.world);
  return s;
}

std::vector<double> read(const Fixture& s, RobotId robot, std::string_view name) {
  std::vector<double> out;
  s.plugin->read(s.world, robot, name, out);
  return out;
}

void join(Fixture& s, RobotId robot, std::uint32_t event) {
  const double id = event;
  s.plugin->request(s.world, robot, "join", std::span<const double>(&id, 1));
}

// The event's position, seen by a robot standing on it with a radius that covers the arena.
Vec2 event_position(std::uint32_t event, ParamOverrides overrides, std::uint64_t seed = 7) {
  overrides["discover_radius_m"] = 1000.0;
  Fixture s = make(1, overrides, seed);
  s.world.positions[0] = Vec2(250.0, 250.0);
  const std::vector<double> view = read(s, 0, "events_in_view");
  return {view.at(6 * event + 1), view.at(6 * event + 2)};
}

void run_steps(Fixture& s, int steps) {
  for (int i = 0; i < steps; ++i) s.world.step(*s.plugin);
}

TEST(TaskEventsTest, OffersItsReadingsAndRequests) {
  Fixture s = make(2, {});
  EXPECT_EQ(s.plugin->readings(),
            (std::vector<std::string>{"battery", "skills", "events_in_view", "charger", "joined"}));
  EXPECT_EQ(s.plugin->requests(), (std::vector<std::string>{"join", "leave"}));
  EXPECT_EQ(read(s, 0, "battery"), (std::vector<double>{1.0, 0.0}));
  EXPECT_EQ(read(s, 0, "charger"), (std::vector<double>{250.0, 250.0, 10.0}));
  EXPECT_TRUE(read(s, 1, "joined").empty());
  EXPECT_EQ(read(s, 1, "skills").size(), 1u);
}

TEST(TaskEventsTest, EventsStayInsideTheMarginAndDoNotDependOnTheSwarm) {
  const ParamOverrides overrides{{"events", std::int64_t{20}}, {"discover_radius_m", 1000.0}};
  Fixture small = make(1, overrides);
  Fixture large = make(40, overrides);
  small.world.positions[0] = large.world.positions[0] = Vec2(250.0, 250.0);
  const std::vector<double> a = read(small, 0, "events_in_view");
  ASSERT_EQ(a.size(), 20u * 6u);
  EXPECT_EQ(a, read(large, 0, "events_in_view"));
  for (std::size_t e = 0; e < 20; ++e) {
    EXPECT_EQ(a[6 * e], static_cast<double>(e));
    EXPECT_GE(a[6 * e + 1], 25.0);
    EXPECT_LE(a[6 * e + 1], 475.0);
    EXPECT_GE(a[6 * e + 2], 25.0);
    EXPECT_LE(a[6 * e + 2], 475.0);
    EXPECT_TRUE(a[6 * e + 3] == 0.0 || a[6 * e + 3] == 1.0);
    EXPECT_EQ(a[6 * e + 4], 4.0);
  }
}

TEST(TaskEventsTest, RobotsDiscoverEventsOnlyWithinTheRadius) {
  const ParamOverrides one{{"events", std::int64_t{1}}};
  const Vec2 at = event_position(0, one);
  Fixture s = make(2, one);
  s.world.positions[0] = at + Vec2(0.0, 49.9);
  s.world.positions[1] = at + Vec2(0.0, -50.1);
  EXPECT_EQ(read(s, 0, "events_in_view").size(), 6u);
  EXPECT_TRUE(read(s, 1, "events_in_view").empty());
}

TEST(TaskEventsTest, ServicedOnlyWhenEnoughRobotsAreThereTogetherForTheServiceTime) {
  // One skill type: every robot can service every event.
  const ParamOverrides params{{"events", std::int64_t{2}}, {"skill_types", std::int64_t{1}}};
  const Vec2 at = event_position(0, params);
  Fixture s = make(5, params);
  for (RobotId r = 0; r < 4; ++r) s.world.positions[r] = at + Vec2(1.0 * r, 0.0);
  for (RobotId r = 0; r < 3; ++r) join(s, r, 0);
  run_steps(s, 600);  // three robots for 60 s: not enough
  EXPECT_EQ(read(s, 0, "joined"), (std::vector<double>{0.0, 3.0, 0.0}));

  EXPECT_EQ(s.world.shown.at(0).state, "being serviced");  // what the viewer draws
  EXPECT_EQ(s.world.shown.at(1).state, "unserviced");
  EXPECT_EQ(s.world.shown.at(0).kind, "event");
  EXPECT_EQ(s.world.shown.at(0).position, at);
  EXPECT_EQ(s.world.shown.at(2).kind, "charger");  // after the events
  EXPECT_EQ(s.world.shown.at(2).position, Vec2(250.0, 250.0));

  join(s, 3, 0);
  run_steps(s, 499);
  const std::vector<double> joined = read(s, 0, "joined");
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_EQ(joined[1], 4.0);
  EXPECT_NEAR(joined[2], 49.9, 1e-9);
  EXPECT_FALSE(s.world.recorded.contains("events_serviced"));

  run_steps(s, 1);  // 50 s together
  EXPECT_TRUE(read(s, 0, "joined").empty());
  ASSERT_EQ(s.world.recorded.at("events_serviced").size(), 1u);
  EXPECT_NEAR(s.world.recorded.at("events_serviced")[0], 110.0, 1e-9);
  EXPECT_FALSE(s.plugin->task_done());  // one event left
  EXPECT_EQ(s.world.shown.at(0).state, "serviced");
  s.world.positions[4] = at;
  EXPECT_TRUE(read(s, 4, "events_in_view").empty() ||
              read(s, 4, "events_in_view")[0] != 0.0);  // a serviced event is not seen
}

TEST(TaskEventsTest, TheServiceClockRestartsWhenARobotLeavesAndFarRobotsDoNotCount) {
  const ParamOverrides params{{"events", std::int64_t{1}}, {"skill_types", std::int64_t{1}}};
  const Vec2 at = event_position(0, params);
  Fixture s = make(5, params);
  for (RobotId r = 0; r < 4; ++r) s.world.positions[r] = at;
  s.world.positions[4] = at + Vec2(10.5, 0.0);  // just outside the 10 m service radius
  for (RobotId r = 0; r < 5; ++r) join(s, r, 0);
  run_steps(s, 300);
  s.plugin->request(s.world, 3, "leave", {});
  run_steps(s, 1);
  EXPECT_EQ(read(s, 0, "joined"), (std::vector<double>{0.0, 3.0, 0.0}));
  join(s, 3, 0);
  run_steps(s, 499);
  EXPECT_FALSE(s.plugin->task_done());
  run_steps(s, 1);
  EXPECT_TRUE(s.plugin->task_done());
  // The far robot did not service it, so it keeps its join no more but was not rewarded either.
  EXPECT_TRUE(read(s, 4, "joined").empty());
}

TEST(TaskEventsTest, JoinRefusesWhatTheRobotCannotDo) {
  const ParamOverrides params{{"events", std::int64_t{6}}};  // two skill types, one per robot
  Fixture s = make(1, params);
  const double skill = read(s, 0, "skills").at(0);
  s.world.positions[0] = Vec2(250.0, 250.0);
  std::vector<double> all;
  Fixture seer = make(1, {{"events", std::int64_t{6}}, {"discover_radius_m", 1000.0}});
  seer.world.positions[0] = Vec2(250.0, 250.0);
  all = read(seer, 0, "events_in_view");
  bool refused_one = false;
  for (std::uint32_t e = 0; e < 6; ++e) {
    if (all[6 * e + 3] == skill) {
      EXPECT_NO_THROW(join(s, 0, e));
    } else {
      EXPECT_THROW(join(s, 0, e), std::invalid_argument);
      refused_one = true;
    }
  }
  EXPECT_TRUE(refused_one) << "seed 7 gives six events of one skill; pick another seed";
  EXPECT_THROW(join(s, 0, 6), std::invalid_argument);
  const std::vector<double> two{0.0, 1.0};
  EXPECT_THROW(s.plugin->request(s.world, 0, "join", two), std::invalid_argument);
  EXPECT_THROW(s.plugin->request(s.world, 0, "leave", two), std::invalid_argument);
}

TEST(TaskEventsTest, DrivingDrainsTheBatteryUntilTheRobotIsSwitchedOff) {
  Fixture s = make(1, {});
  // A full battery drives 200 s x 5 m/s = 1000 m.
  const auto drive = [&](double metres) {
    s.world.positions[0] += Vec2(0.0, metres);
    s.world.step(*s.plugin);
  };
  run_steps(s, 100);  // standing still costs nothing
  EXPECT_EQ(read(s, 0, "battery"), (std::vector<double>{1.0, 0.0}));
  for (int i = 0; i < 6; ++i) drive(100.0);
  EXPECT_NEAR(read(s, 0, "battery")[0], 0.4, 1e-12);
  drive(1.0);
  EXPECT_EQ(read(s, 0, "battery")[1], 1.0);  // low: go to the charger
  EXPECT_FALSE(s.world.off[0]);
  for (int i = 0; i < 4; ++i) drive(100.0);
  EXPECT_TRUE(s.world.off[0]);
  EXPECT_EQ(read(s, 0, "battery")[0], 0.0);
  ASSERT_EQ(s.world.recorded.at("out_of_energy").size(), 1u);
}

TEST(TaskEventsTest, TheChargerChargesAndServicingRecharges) {
  const ParamOverrides params{{"events", std::int64_t{1}},
                              {"skill_types", std::int64_t{1}},
                              {"required_robots", std::int64_t{1}}};
  const Vec2 at = event_position(0, params);
  Fixture s = make(2, params);
  // Robot 0 drives 500 m to the event; robot 1 drives 500 m and parks at the charger.
  s.world.positions[0] = at + Vec2(0.0, 500.0);
  s.world.positions[1] = Vec2(250.0, 750.0);
  s.plugin->setup(s.world);  // again: the robots start where they are now
  s.world.positions[0] = at;
  s.world.positions[1] = Vec2(250.0, 250.0);
  s.plugin->post_step(s.world);  // the drive: 500 m each, half a battery; robot 1 then charges
  EXPECT_NEAR(read(s, 0, "battery")[0], 0.5, 1e-12);
  EXPECT_NEAR(read(s, 1, "battery")[0], 0.5 + 0.1 / 20.0, 1e-12);
  join(s, 0, 0);
  run_steps(s, 50);  // 5 s at the charger: a quarter of a battery
  EXPECT_NEAR(read(s, 1, "battery")[0], 0.755, 1e-9);
  run_steps(s, 50);
  EXPECT_EQ(read(s, 1, "battery")[0], 1.0);  // full, and no further
  run_steps(s, 400);                         // the event's 50 s
  EXPECT_TRUE(s.plugin->task_done());
  EXPECT_EQ(read(s, 0, "battery")[0], 1.0);  // the reward
  ASSERT_EQ(s.world.recorded.at("completion_time_s").size(), 1u);
}

TEST(TaskEventsTest, EndRecordsDistancesAndWhatIsLeft) {
  Fixture s = make(3, {{"events", std::int64_t{2}}});
  s.world.positions[1] += Vec2(3.0, 4.0);
  s.world.step(*s.plugin);
  s.plugin->end(s.world);
  EXPECT_EQ(s.world.recorded.at("distance_m"), (std::vector<double>{0.0, 5.0, 0.0}));
  EXPECT_EQ(s.world.recorded.at("events_unserviced"), (std::vector<double>{2.0}));
  EXPECT_FALSE(s.plugin->task_done());
}

TEST(TaskEventsTest, SaysWhichEventsNoRunCouldService) {
  Fixture enough = make(20, {{"events", std::int64_t{5}}, {"skill_types", std::int64_t{1}}});
  EXPECT_EQ(enough.world.recorded.at("infeasible_events"), (std::vector<double>{0.0}));
  // Three robots cannot make the four an event needs.
  Fixture few = make(3, {{"events", std::int64_t{5}}, {"skill_types", std::int64_t{1}}});
  EXPECT_EQ(few.world.recorded.at("infeasible_events"), (std::vector<double>{5.0}));
}

TEST(TaskEventsTest, RefusesMoreSkillsPerRobotThanThereAre) {
  EXPECT_THROW(TaskEvents(plugin_args<TaskEvents>({{"skills_per_robot", std::int64_t{3}}})),
               std::invalid_argument);
}

}  // namespace
}  // namespace swarmnet::task_events
