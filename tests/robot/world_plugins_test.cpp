// World plugins in the robot half (robot/world_plugins.hpp): called around the controllers every
// step, answering readings and requests by name, switching robots off and ending the task.
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/robot_world.hpp"
#include "robot_test_support.hpp"

namespace swarmnet::test {
namespace {

const std::string kFixtures = SWARMNET_TEST_FIXTURE_DIR;

class WorldPluginsTest : public ::testing::Test {
 protected:
  PluginLoader loader_{{kFixtures}};

  RobotSettings settings(const Overrides& world = {}, const Overrides& probe = {}) {
    RobotSettings s = make_settings(loader_, 3, 50.0, 50.0);
    s.robots.controllers.push_back(
        make_choice(loader_, "world_probe", PluginKind::controller, probe));
    s.worlds.push_back(make_choice(loader_, "test_world", PluginKind::world, world));
    return s;
  }

  static void run(RobotWorld& world, int steps) {
    std::vector<AppMessage> sent;
    for (int i = 0; i < steps; ++i) world.step({}, sent);
  }
};

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}

TEST_F(WorldPluginsTest, SamplesOfControllersAndWorldsAreRowsInCallOrder) {
  RobotSettings s = settings({{"sample_steps", true}}, {{"sample_clock", true}});
  std::ostringstream series;
  int opened = 0;
  s.open_series = [&]() -> std::ostream& {
    ++opened;
    return series;
  };
  RobotWorld world(s, loader_);
  run(world, 2);
  // Each step: robots 0..2 at its start read the clock, then the world's post_step at its end.
  EXPECT_EQ(series.str(),
            "time_ns,robot,series,value\n"
            "0,0,clock_s,0\n0,1,clock_s,0\n0,2,clock_s,0\n"
            "100000000,,post_steps,1\n"
            "100000000,0,clock_s,0.1\n100000000,1,clock_s,0.1\n100000000,2,clock_s,0.1\n"
            "200000000,,post_steps,2\n");
  EXPECT_EQ(opened, 1);
  EXPECT_EQ(world.series_rows(), 8U);
  EXPECT_EQ(world.robot_metrics().of(1, "clock_s").count, 2U);
  EXPECT_EQ(world.robot_metrics().of(1, "clock_s").max, 0.1);
}

TEST_F(WorldPluginsTest, ControllersReadTheWorldAtTheStartOfEachStep) {
  RobotWorld world(settings(), loader_);
  run(world, 10);
  const MetricSummary clock = world.controller_metrics().at("clock_s");
  EXPECT_EQ(clock.count, 30u);
  EXPECT_DOUBLE_EQ(clock.min, 0.0);
  EXPECT_NEAR(clock.max, 0.9, 1e-12);  // pre_step's time: the step's start
  EXPECT_FALSE(world.task_done());
  world.end_worlds();
  EXPECT_EQ(world.world_metrics().at("post_steps").sum, 10.0);
  EXPECT_EQ(world.world_metrics().at("robots").sum, 3.0);
}

TEST_F(WorldPluginsTest, ASwitchedOffRobotStandsStillAndItsControllersStop) {
  RobotWorld world(settings({}, {{"halt_robot", std::int64_t{1}}, {"halt_at_s", 0.5}}), loader_);
  run(world, 6);  // robot 1 asks at 0.5 s, during the sixth step: it moves in that step still
  EXPECT_EQ(world.bodies()[1].left_mps, 1.0);
  run(world, 10);
  // The fixtures' physics is a stand-in that moves nothing: the wheels tell.
  EXPECT_EQ(world.bodies()[1].left_mps, 0.0);
  EXPECT_EQ(world.bodies()[1].right_mps, 0.0);
  EXPECT_EQ(world.bodies()[0].left_mps, 1.0);
  EXPECT_EQ(world.bodies()[2].right_mps, 1.0);
  // Robots 0 and 2 read the clock 16 times, robot 1 only in the first 6 steps.
  EXPECT_EQ(world.controller_metrics().at("clock_s").count, 16u + 16u + 6u);
}

TEST_F(WorldPluginsTest, TheTaskEndsAfterTheStepThatDidIt) {
  RobotWorld world(settings({{"done_after_steps", std::int64_t{4}}}), loader_);
  run(world, 3);
  EXPECT_FALSE(world.task_done());
  run(world, 1);
  EXPECT_TRUE(world.task_done());
  EXPECT_EQ(world.done_by(), std::optional<std::string>("test_world"));
}

TEST_F(WorldPluginsTest, UnknownNamesAreRefusedWithWhatIsOffered) {
  RobotWorld world(settings({{"reading_name", std::string("time")}}), loader_);
  const std::string message = error_of([&] { run(world, 1); });
  EXPECT_NE(message.find("no world plugin offers the reading 'clock'"), std::string::npos)
      << message;
  EXPECT_NE(message.find("offer: time"), std::string::npos) << message;

  RobotWorld asking(settings({}, {{"bad_request", true}}), loader_);
  const std::string request = error_of([&] { run(asking, 1); });
  EXPECT_NE(request.find("request 'fly'"), std::string::npos) << request;
  EXPECT_NE(request.find("offer: halt"), std::string::npos) << request;
}

TEST_F(WorldPluginsTest, SeveralWorldsRunButANameHasOneOwner) {
  RobotSettings two = settings();
  two.worlds.push_back(make_choice(loader_, "test_world", PluginKind::world,
                                   {{"reading_name", std::string("other")},
                                    {"request_name", std::string("other")},
                                    {"done_after_steps", std::int64_t{2}}}));
  RobotWorld world(two, loader_);
  run(world, 2);
  EXPECT_TRUE(world.task_done());  // the second world's task

  RobotSettings clash = settings();
  clash.worlds.push_back(make_choice(loader_, "test_world", PluginKind::world,
                                     {{"reading_name", std::string("other")}}));
  const std::string message = error_of([&] { RobotWorld(clash, loader_); });
  EXPECT_NE(message.find("both offer the request 'halt'"), std::string::npos) << message;
  EXPECT_NE(message.find("(world.0)"), std::string::npos) << message;
  EXPECT_NE(message.find("(world.1)"), std::string::npos) << message;
}

// post_step sees the bodies where the physics put them. The fixtures' kinematic2d is a stand-in
// that moves nothing, so this runs on ode, which no fixture shadows.
TEST_F(WorldPluginsTest, PostStepSeesTheRobotsWhereThePhysicsMovedThem) {
  RobotSettings s = settings();
  s.arena = Arena{500.0, 500.0, {}};
  s.robots.placement = Rect{200.0, 200.0, 300.0, 300.0};
  s.physics = make_choice(loader_, "ode", PluginKind::physics);
  RobotWorld world(s, loader_);
  const Vec2 start = world.bodies()[0].position;
  run(world, 20);
  const double moved = (world.bodies()[0].position - start).norm();
  ASSERT_GT(moved, 0.5);  // 2 s at up to 1 m/s
  // Summed step by step between the hooks, at least the net displacement.
  EXPECT_GE(world.world_metrics().at("robot0_moved_m").sum, moved - 1e-9);
}

TEST_F(WorldPluginsTest, AWorldsFailureNamesTheWorldAndTheHook) {
  RobotWorld world(settings({{"fail_in", std::string("post_step")}}), loader_);
  const std::string message = error_of([&] { run(world, 1); });
  EXPECT_NE(message.find("world test_world (world.0), post_step at 0.1"), std::string::npos)
      << message;
  EXPECT_NE(message.find("the fixture fails in post_step"), std::string::npos) << message;
}

}  // namespace
}  // namespace swarmnet::test
