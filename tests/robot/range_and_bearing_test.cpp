// The range-and-bearing device (robot/range_and_bearing_device.hpp): who sees whom (range, walls,
// objects and robots in between), the range and bearing read, the data carried, noise and loss;
// then through RobotWorld and the robot contexts a controller sees.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "robot/range_and_bearing_device.hpp"
#include "robot/robot_context.hpp"
#include "robot/robot_placement.hpp"
#include "robot/robot_world.hpp"
#include "robot_test_support.hpp"
#include "swarmnet/proximity_ring.hpp"

namespace swarmnet {
namespace {

using test::make_body;
using test::make_choice;
using test::make_settings;

constexpr double kPi = std::numbers::pi;

RangeAndBearingConfig device_config(double range_m = 3.0) {
  RangeAndBearingConfig config;
  config.enabled = true;
  config.range_m = range_m;
  return config;
}

// One sense of `bodies` in a 10 x 10 m arena (with `arena`'s obstacles and objects).
class Scene {
 public:
  explicit Scene(std::vector<RobotBody> bodies, RangeAndBearingConfig config = device_config(),
                 Arena arena = Arena{10.0, 10.0, {}})
      : arena_(std::move(arena)),
        bodies_(std::move(bodies)),
        device_(config, bodies_.size(), /*seed*/ 5) {}

  RangeAndBearingDevice& device() { return device_; }
  std::vector<ObjectPose> object_poses;
  std::vector<std::uint8_t> switched_off;

  std::span<const RangeAndBearingReading> sense(RobotId robot, std::uint64_t step = 0) {
    device_.sense(arena_, bodies_, object_poses, switched_off, step);
    return device_.readings(robot);
  }
  // The ids robot `robot` sees.
  std::vector<RobotId> seen_by(RobotId robot) {
    std::vector<RobotId> ids;
    for (const RangeAndBearingReading& r : sense(robot)) ids.push_back(r.robot);
    return ids;
  }

 private:
  Arena arena_;
  std::vector<RobotBody> bodies_;
  RangeAndBearingDevice device_;
};

using Ids = std::vector<RobotId>;

// A `width_m` x `height_m` arena whose movable objects are a cylinder and a box of these sizes
// (their poses are the test's object_poses).
Arena arena_with_objects(double width_m, double height_m, double cylinder_radius_m, double box_x_m,
                         double box_y_m) {
  Arena arena{width_m, height_m, {}};
  ArenaObject cylinder;
  cylinder.shape = ArenaObject::Shape::cylinder;
  cylinder.radius_m = cylinder_radius_m;
  ArenaObject box;
  box.size_x_m = box_x_m;
  box.size_y_m = box_y_m;
  arena.objects = {cylinder, box};
  return arena;
}

TEST(RangeAndBearing, AWallBetweenTheCentresBlocksTheLineAndOnlyThen) {
  const Arena walled{10.0, 10.0, {Rect{4.9, 2.0, 5.1, 8.0}}};
  Scene across({make_body(3.0, 5.0, 0.0), make_body(7.0, 5.0, 0.0)}, device_config(), walled);
  EXPECT_EQ(across.seen_by(0), Ids{});
  EXPECT_EQ(across.seen_by(1), Ids{});
  // Above the wall's end, and short of the wall: seen.
  Scene above({make_body(3.5, 9.0, 0.0), make_body(6.5, 9.0, 0.0)}, device_config(), walled);
  EXPECT_EQ(above.seen_by(0), Ids{1});
  EXPECT_EQ(above.seen_by(1), Ids{0});
  Scene before({make_body(3.0, 5.0, 0.0), make_body(4.8, 5.0, 0.0)}, device_config(), walled);
  EXPECT_EQ(before.seen_by(0), Ids{1});
  // Diagonals past the wall's top: one clears it (y = 8.4 at x = 4.9), one clips it (7.9).
  Scene clears({make_body(4.0, 7.5, 0.0), make_body(6.0, 9.5, 0.0)}, device_config(), walled);
  EXPECT_EQ(clears.seen_by(0), Ids{1});
  Scene clips({make_body(4.0, 7.0, 0.0), make_body(6.0, 9.0, 0.0)}, device_config(), walled);
  EXPECT_EQ(clips.seen_by(0), Ids{});
}

TEST(RangeAndBearing, ARobotBetweenBlocksTheLineButNotItsNeighbours) {
  // 0 -- 1 -- 2 on a line: the middle robot hides the ends from each other.
  Scene line({make_body(2.0, 5.0, 0.0), make_body(3.0, 5.0, 0.0), make_body(4.0, 5.0, 0.0)});
  EXPECT_EQ(line.seen_by(0), Ids{1});
  EXPECT_EQ(line.seen_by(1), (Ids{0, 2}));
  EXPECT_EQ(line.seen_by(2), Ids{1});
  // Moved 0.1 m off the line (more than its 0.085 m radius), it no longer does.
  Scene aside({make_body(2.0, 5.0, 0.0), make_body(3.0, 5.1, 0.0), make_body(4.0, 5.0, 0.0)});
  EXPECT_EQ(aside.seen_by(0), (Ids{1, 2}));
  // 0.08 m off the line, its disc still crosses it.
  Scene grazing({make_body(2.0, 5.0, 0.0), make_body(3.0, 5.08, 0.0), make_body(4.0, 5.0, 0.0)});
  EXPECT_EQ(grazing.seen_by(0), Ids{1});
  // A robot switched off neither emits nor receives, but its body still blocks.
  line.switched_off = {0, 1, 0};
  EXPECT_EQ(line.seen_by(0), Ids{});
  EXPECT_EQ(line.seen_by(1), Ids{});
  // Pending (2) is not yet off.
  line.switched_off = {0, 2, 0};
  EXPECT_EQ(line.seen_by(0), Ids{1});
}

TEST(RangeAndBearing, AMovableObjectBetweenBlocksTheLine) {
  const Arena arena = arena_with_objects(10.0, 10.0, 0.3, 1.0, 0.2);
  Scene scene({make_body(3.0, 5.0, 0.0), make_body(7.0, 5.0, 0.0), make_body(3.0, 2.0, 0.0),
               make_body(5.0, 2.0, 0.0)},
              device_config(5.0), arena);
  // The cylinder between 0 and 1; the box, turned upright, between 2 and 3.
  scene.object_poses = {ObjectPose{Vec2(5.0, 5.0), 0.0}, ObjectPose{Vec2(4.0, 2.0), kPi / 2}};
  EXPECT_EQ(scene.seen_by(0), (Ids{2, 3}));
  EXPECT_EQ(scene.seen_by(2), (Ids{0, 1}));
  // Moved away, they block nothing.
  scene.object_poses = {ObjectPose{Vec2(5.0, 8.0), 0.0}, ObjectPose{Vec2(8.0, 8.0), 0.0}};
  EXPECT_EQ(scene.seen_by(0), (Ids{1, 2, 3}));
}

TEST(RangeAndBearing, RangeIsInclusiveAndCutsJustBeyond) {
  Scene inside({make_body(1.0, 1.0, 0.0), make_body(4.0 - 1e-9, 1.0, 0.0)});
  EXPECT_EQ(inside.seen_by(0), Ids{1});
  Scene at({make_body(1.0, 1.0, 0.0), make_body(4.0, 1.0, 0.0)});
  EXPECT_EQ(at.seen_by(0), Ids{1});
  Scene beyond({make_body(1.0, 1.0, 0.0), make_body(4.0 + 1e-9, 1.0, 0.0)});
  EXPECT_EQ(beyond.seen_by(0), Ids{});
  EXPECT_EQ(beyond.seen_by(1), Ids{});
  // A shorter range.
  Scene short_range({make_body(1.0, 1.0, 0.0), make_body(1.0, 1.79, 0.0)}, device_config(0.8));
  EXPECT_EQ(short_range.seen_by(0), Ids{1});
  EXPECT_DOUBLE_EQ(short_range.sense(0)[0].range_m, 0.79);
}

TEST(RangeAndBearing, BearingIsCounterClockwiseFromTheHeadingInEveryQuadrant) {
  const std::vector<RobotBody> around = {make_body(5.0, 5.0, 0.0), make_body(6.0, 6.0, 0.0),
                                         make_body(4.0, 6.0, 0.0), make_body(4.0, 4.0, 0.0),
                                         make_body(6.0, 4.0, 0.0), make_body(3.5, 5.0, 0.0)};
  const auto bearings_seen_by_0 = [](std::vector<RobotBody> bodies) {
    Scene scene(std::move(bodies));
    std::vector<double> bearings;
    for (const RangeAndBearingReading& r : scene.sense(0)) bearings.push_back(r.bearing_rad);
    return bearings;
  };
  // Heading +x: the four diagonals and straight behind (pi, not -pi).
  std::vector<double> bearings = bearings_seen_by_0(around);
  ASSERT_EQ(bearings.size(), 5U);
  EXPECT_NEAR(bearings[0], kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[1], 3 * kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[2], -3 * kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[3], -kPi / 4, 1e-12);
  EXPECT_EQ(bearings[4], kPi);
  // Heading +y: every bearing a quarter turn less, wrapped into (-pi, pi].
  std::vector<RobotBody> turned = around;
  turned[0].heading_rad = kPi / 2;
  bearings = bearings_seen_by_0(turned);
  ASSERT_EQ(bearings.size(), 5U);
  EXPECT_NEAR(bearings[0], -kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[1], kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[2], 3 * kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[3], -3 * kPi / 4, 1e-12);
  EXPECT_NEAR(bearings[4], kPi / 2, 1e-12);
  // The ranges are the centres' distances.
  Scene scene(around);
  const auto readings = scene.sense(0);
  EXPECT_DOUBLE_EQ(readings[0].range_m, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(readings[4].range_m, 1.5);
}

TEST(RangeAndBearing, ReadingsCarryTheDataSetBeforeTheSenseZeroPadded) {
  Scene scene({make_body(3.0, 5.0, 0.0), make_body(5.0, 5.0, 0.0)});
  const auto bytes = [](std::span<const std::byte> data) {
    std::vector<int> values;
    for (const std::byte b : data) values.push_back(std::to_integer<int>(b));
    return values;
  };
  // Zeros before anything is set.
  EXPECT_EQ(bytes(scene.sense(0)[0].data), std::vector<int>(10, 0));
  const std::array<std::byte, 2> first{std::byte{0xab}, std::byte{0xcd}};
  scene.device().set_data(1, first);
  const auto readings = scene.sense(0, 1);
  EXPECT_EQ(bytes(readings[0].data), (std::vector<int>{0xab, 0xcd, 0, 0, 0, 0, 0, 0, 0, 0}));
  // Data set after a sense shows only from the next one; the last set stays until set again.
  const std::array<std::byte, 1> second{std::byte{7}};
  scene.device().set_data(1, second);
  EXPECT_EQ(bytes(readings[0].data)[0], 0xab);
  EXPECT_EQ(bytes(scene.sense(0, 2)[0].data), (std::vector<int>{7, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(bytes(scene.sense(0, 3)[0].data)[0], 7);
  EXPECT_EQ(bytes(scene.sense(1, 3)[0].data), std::vector<int>(10, 0));  // robot 0 set nothing
  // Full size is accepted, one byte more refused with both sizes named.
  const std::vector<std::byte> full(10, std::byte{1});
  scene.device().set_data(0, full);
  const std::vector<std::byte> too_long(11, std::byte{1});
  try {
    scene.device().set_data(0, too_long);
    FAIL() << "11 bytes accepted";
  } catch (const std::invalid_argument& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("11 bytes"), std::string::npos) << text;
    EXPECT_NE(text.find("10 (robots.range_and_bearing.data_bytes)"), std::string::npos) << text;
  }
  // No data at all: the readings still come, with empty data.
  RangeAndBearingConfig none = device_config();
  none.data_bytes = 0;
  Scene bare({make_body(3.0, 5.0, 0.0), make_body(5.0, 5.0, 0.0)}, none);
  bare.device().set_data(1, {});
  ASSERT_EQ(bare.sense(0).size(), 1U);
  EXPECT_TRUE(bare.sense(0)[0].data.empty());
  EXPECT_THROW(bare.device().set_data(1, first), std::invalid_argument);
}

// Mean and standard deviation of `values`.
std::pair<double, double> moments(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  const double mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (const double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / static_cast<double>(values.size() - 1))};
}

TEST(RangeAndBearing, NoiseIsGaussianWithTheConfiguredSpread) {
  RangeAndBearingConfig config = device_config();
  config.range_noise_sd_m = 0.05;
  config.bearing_noise_sd_rad = 0.1;
  Scene scene({make_body(3.0, 5.0, 0.0), make_body(5.0, 5.0, 0.0)}, config);
  constexpr std::size_t kDraws = 4000;
  std::vector<double> ranges;
  std::vector<double> range_errors;
  std::vector<double> bearing_errors;
  for (std::uint64_t step = 0; step < kDraws; ++step) {
    const auto readings = scene.sense(0, step);
    ASSERT_EQ(readings.size(), 1U);
    ranges.push_back(readings[0].range_m);
    range_errors.push_back(readings[0].range_m - 2.0);
    bearing_errors.push_back(readings[0].bearing_rad);  // the true bearing is 0
  }
  // Within 4 standard errors: the mean's is sd / sqrt(n), the standard deviation's about
  // sd / sqrt(2 (n - 1)). A correct model fails either with a probability of about 6e-5.
  const double n = static_cast<double>(kDraws);
  const auto check = [n](const std::vector<double>& errors, double sd) {
    const auto [mean, spread] = moments(errors);
    EXPECT_NEAR(mean, 0.0, 4.0 * sd / std::sqrt(n));
    EXPECT_NEAR(spread, sd, 4.0 * sd / std::sqrt(2.0 * (n - 1.0)));
  };
  check(range_errors, 0.05);
  check(bearing_errors, 0.1);
  // Same seed and step, same draw; another step, another.
  EXPECT_EQ(std::bit_cast<std::uint64_t>(scene.sense(0, 17)[0].range_m),
            std::bit_cast<std::uint64_t>(ranges[17]));
  const double at_17 = scene.sense(0, 17)[0].range_m;  // a reading lasts until the next sense
  EXPECT_NE(at_17, scene.sense(0, 18)[0].range_m);
}

TEST(RangeAndBearing, NoisyRangesStayAtOrAboveZeroAndBearingsInTheHalfOpenCircle) {
  RangeAndBearingConfig config = device_config();
  config.range_noise_sd_m = 1.0;
  config.bearing_noise_sd_rad = 0.5;
  // Robot 1 straight behind robot 0, 0.2 m away: half of the bearings wrap.
  Scene scene({make_body(5.0, 5.0, 0.0), make_body(4.8, 5.0, 0.0)}, config);
  std::size_t zero = 0;
  std::size_t negative_side = 0;
  for (std::uint64_t step = 0; step < 2000; ++step) {
    const RangeAndBearingReading r = scene.sense(0, step)[0];
    ASSERT_GE(r.range_m, 0.0);
    ASSERT_GT(r.bearing_rad, -kPi);
    ASSERT_LE(r.bearing_rad, kPi);
    zero += r.range_m == 0.0 ? 1 : 0;
    negative_side += r.bearing_rad < 0.0 ? 1 : 0;
  }
  EXPECT_GT(zero, 500U);  // P(N(0.2, 1) < 0) = 0.42
  EXPECT_GT(negative_side, 800U);
  EXPECT_LT(negative_side, 1200U);
}

TEST(RangeAndBearing, LossDropsTheConfiguredShareOfReadings) {
  RangeAndBearingConfig config = device_config();
  config.loss_probability = 0.3;
  // Robot 0 sees two robots, each reading lost on its own.
  Scene scene({make_body(5.0, 5.0, 0.0), make_body(6.0, 5.0, 0.0), make_body(5.0, 6.0, 0.0)},
              config);
  constexpr std::size_t kSteps = 4000;
  std::array<std::size_t, 3> kept{};
  std::size_t both_lost = 0;
  for (std::uint64_t step = 0; step < kSteps; ++step) {
    const auto readings = scene.sense(0, step);
    for (const RangeAndBearingReading& r : readings) {
      ++kept[r.robot];
      EXPECT_EQ(r.range_m, 1.0) << "a loss draws no noise";
    }
    both_lost += readings.empty() ? 1 : 0;
  }
  const double n = static_cast<double>(kSteps);
  const double tolerance = 4.0 * std::sqrt(0.3 * 0.7 / n);
  EXPECT_NEAR(1.0 - static_cast<double>(kept[1]) / n, 0.3, tolerance);
  EXPECT_NEAR(1.0 - static_cast<double>(kept[2]) / n, 0.3, tolerance);
  // Independent: both lost at once about 0.09 of the time.
  EXPECT_NEAR(static_cast<double>(both_lost) / n, 0.09, 4.0 * std::sqrt(0.09 * 0.91 / n));

  config.loss_probability = 1.0;
  Scene deaf({make_body(5.0, 5.0, 0.0), make_body(6.0, 5.0, 0.0)}, config);
  for (std::uint64_t step = 0; step < 100; ++step) EXPECT_TRUE(deaf.sense(0, step).empty());
}

// Noise of the reading of e at r in step k comes from a stream of its own: robots added
// elsewhere, or visited in another order, change no other reading.
TEST(RangeAndBearing, EachReadingDrawsFromItsOwnStream) {
  RangeAndBearingConfig config = device_config();
  config.range_noise_sd_m = 0.1;
  config.bearing_noise_sd_rad = 0.1;
  config.loss_probability = 0.2;
  Scene pair({make_body(3.0, 5.0, 0.0), make_body(5.0, 5.0, 0.0)}, config);
  Scene crowd({make_body(3.0, 5.0, 0.0), make_body(5.0, 5.0, 0.0), make_body(3.0, 6.0, 0.0),
               make_body(2.0, 4.0, 0.0)},
              config);
  std::size_t compared = 0;
  for (std::uint64_t step = 0; step < 200; ++step) {
    const auto alone = pair.sense(0, step);
    const auto among = crowd.sense(0, step);
    const bool kept_alone = !alone.empty();
    const bool kept_among = !among.empty() && among[0].robot == 1;
    ASSERT_EQ(kept_alone, kept_among) << "step " << step;
    if (!kept_alone) continue;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(alone[0].range_m),
              std::bit_cast<std::uint64_t>(among[0].range_m));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(alone[0].bearing_rad),
              std::bit_cast<std::uint64_t>(among[0].bearing_rad));
    ++compared;
  }
  EXPECT_GT(compared, 100U);
}

// Every ordered pair checked against every obstacle, object and robot: what the device's grid
// and direction bins must find exactly.
std::vector<Ids> seen_by_every_robot_brute_force(const Arena& arena,
                                                 const std::vector<RobotBody>& bodies,
                                                 const std::vector<ObjectPose>& poses,
                                                 const std::vector<std::uint8_t>& off,
                                                 double range_m) {
  std::vector<Ids> seen(bodies.size());
  for (std::size_t r = 0; r < bodies.size(); ++r) {
    if (off[r] == 1) continue;
    const Vec2 origin = bodies[r].position;
    for (std::size_t e = 0; e < bodies.size(); ++e) {
      const Vec2 offset = bodies[e].position - origin;
      const double d = offset.norm();
      if (e == r || off[e] == 1 || d > range_m) continue;
      const Vec2 u = offset / d;
      bool blocked = false;
      for (const Rect& obstacle : arena.obstacles) blocked |= ray_to_rect(obstacle, origin, u) < d;
      for (std::size_t o = 0; o < poses.size(); ++o) {
        blocked |= ray_to_object(arena.objects[o], poses[o], origin, u) < d;
      }
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        if (k == r || k == e) continue;
        blocked |= ray_to_disc(bodies[k].position, bodies[k].radius_m, origin, u) < d;
      }
      if (!blocked) seen[r].push_back(static_cast<RobotId>(e));
    }
  }
  return seen;
}

TEST(RangeAndBearing, FindsExactlyWhatCheckingEveryPairFinds) {
  Arena arena = arena_with_objects(20.0, 20.0, 0.4, 1.5, 0.3);
  arena.obstacles = {Rect{5.0, 5.0, 6.0, 12.0}, Rect{12.0, 14.0, 17.0, 14.5}};
  const std::vector<ObjectPose> poses = {ObjectPose{Vec2(14.0, 6.0), 0.0},
                                         ObjectPose{Vec2(9.0, 16.0), 0.7}};
  RobotBody prototype = make_body(0.0, 0.0, 0.0);
  for (const std::uint32_t count : {2U, 60U, 400U}) {
    const std::vector<RobotBody> bodies =
        place_robots(arena, Rect{0.0, 0.0, 20.0, 20.0}, count, prototype, 11 + count);
    std::vector<std::uint8_t> off(count, 0);
    off[count / 2] = 1;
    for (const double range_m : {0.5, 3.0, 30.0}) {
      RangeAndBearingDevice device(device_config(range_m), count, 3);
      device.sense(arena, bodies, poses, off, 0);
      const auto expected = seen_by_every_robot_brute_force(arena, bodies, poses, off, range_m);
      std::size_t readings = 0;
      for (RobotId r = 0; r < count; ++r) {
        Ids ids;
        for (const RangeAndBearingReading& reading : device.readings(r)) {
          ids.push_back(reading.robot);
          const Vec2 offset = bodies[reading.robot].position - bodies[r].position;
          EXPECT_EQ(reading.range_m, offset.norm());
        }
        EXPECT_EQ(ids, expected[r]) << count << " robots, range " << range_m << ", robot " << r;
        readings += ids.size();
      }
      if (count == 400 && range_m == 3.0) {
        EXPECT_GT(readings, 2000U);  // a busy sky
      }
    }
  }
}

// Through RobotWorld: its contexts serve the device, which senses at the start of every step.
class RangeAndBearingWorldTest : public ::testing::Test {
 protected:
  PluginLoader loader_{{SWARMNET_TEST_FIXTURE_DIR}};

  // Three robots of the rab_probe fixture in a 2 x 2 m arena (the fixtures' physics moves
  // nothing), all within range.
  RobotSettings probes() {
    RobotSettings s = make_settings(loader_, 3, 2.0, 2.0);
    s.robots.controllers.push_back(make_choice(loader_, "rab_probe", PluginKind::controller));
    s.robots.range_and_bearing = device_config();
    return s;
  }
};

TEST_F(RangeAndBearingWorldTest, ControllersReadTheDataSetInThePreviousStep) {
  RobotWorld world(probes(), loader_);
  EXPECT_TRUE(world.range_and_bearing(0).empty()) << "nothing sensed before the first step";
  std::vector<AppMessage> sent;
  for (int i = 0; i < 20; ++i) world.step({}, sent);
  const ControllerMetrics& metrics = world.controller_metrics();
  const MetricSummary& per_step = metrics.at("rab_readings");
  EXPECT_EQ(per_step.count, 60U);
  EXPECT_GT(per_step.sum, 0.0);
  EXPECT_EQ(metrics.at("rab_range_m").count, static_cast<std::size_t>(per_step.sum));
  // Every reading carried its robot's id and the tick it set in the previous step (init()'s in
  // the first), zero-padded.
  EXPECT_EQ(metrics.at("rab_stale").sum, 0.0);
  EXPECT_EQ(metrics.at("rab_wrong_sender").sum, 0.0);
  EXPECT_EQ(metrics.at("rab_unpadded").sum, 0.0);
  // What the last step's controllers read, as the world shows it.
  std::size_t last_step = 0;
  for (RobotId r = 0; r < 3; ++r) {
    for (const RangeAndBearingReading& reading : world.range_and_bearing(r)) {
      EXPECT_NE(reading.robot, r);
      EXPECT_EQ(std::to_integer<int>(reading.data[1]), 19);  // set in the 19th step
      ++last_step;
    }
  }
  EXPECT_GT(last_step, 0U);
}

TEST_F(RangeAndBearingWorldTest, WithoutTheKeyTheContextRefusesNamingIt) {
  RobotWorldState state;
  state.bodies.resize(2);
  WorldRobotContext robot(state, 1);
  const std::array<std::byte, 1> data{};
  for (const auto& call :
       std::vector<std::function<void()>>{[&] { (void)robot.range_and_bearing(); },
                                          [&] { robot.set_range_and_bearing_data(data); }}) {
    try {
      call();
      FAIL() << "the device answered without the key";
    } catch (const std::logic_error& error) {
      EXPECT_NE(std::string(error.what()).find("robots.range_and_bearing.enabled: true"),
                std::string::npos)
          << error.what();
    }
  }
  // A run without the key: the probe's first step refuses.
  RobotSettings settings = probes();
  settings.robots.range_and_bearing.enabled = false;
  EXPECT_THROW((RobotWorld{settings, loader_}), std::logic_error);  // init() sets its data
  const RobotWorld without(make_settings(loader_, 3, 2.0, 2.0), loader_);
  EXPECT_TRUE(without.range_and_bearing(0).empty());
}

TEST_F(RangeAndBearingWorldTest, TheContextRefusesMoreDataThanTheDeviceCarries) {
  RobotWorldState state;
  state.bodies.resize(2);
  RangeAndBearingConfig config = device_config();
  config.data_bytes = 4;
  RangeAndBearingDevice device(config, 2, 1);
  state.range_and_bearing = &device;
  WorldRobotContext robot(state, 1);
  const std::array<std::byte, 5> data{};
  try {
    robot.set_range_and_bearing_data(data);
    FAIL() << "5 bytes accepted";
  } catch (const std::invalid_argument& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("robot 1"), std::string::npos) << text;
    EXPECT_NE(text.find("5 bytes"), std::string::npos) << text;
    EXPECT_NE(text.find("4 (robots.range_and_bearing.data_bytes)"), std::string::npos) << text;
  }
  robot.set_range_and_bearing_data(std::span(data).first(4));
  EXPECT_TRUE(robot.range_and_bearing().empty());
}

}  // namespace
}  // namespace swarmnet
