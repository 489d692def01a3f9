// The ns-2 mobility trace: its lines are printf's ("%.6f", "%zu"), which ns-2's and ns-3's
// readers parse, for every value a run can produce.
#include "outputs/mobility_trace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace swarmnet {
namespace {

std::string initial_lines(const std::vector<Vec2>& positions) {
  std::string text;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    char line[1200];
    std::snprintf(line, sizeof line,
                  "$node_(%zu) set X_ %.6f\n$node_(%zu) set Y_ %.6f\n$node_(%zu) set Z_ 0.000000\n",
                  i, positions[i].x(), i, positions[i].y(), i);
    text += line;
  }
  return text;
}

std::string setdest_lines(double start_s, double span_s, const std::vector<Vec2>& from,
                          const std::vector<Vec2>& to) {
  std::string text;
  for (std::size_t i = 0; i < to.size(); ++i) {
    const double distance = (to[i] - from[i]).norm();
    if (distance == 0.0) continue;
    char line[1200];
    std::snprintf(line, sizeof line, "$ns_ at %.6f \"$node_(%zu) setdest %.6f %.6f %.6f\"\n",
                  start_s, i, to[i].x(), to[i].y(), distance / span_s);
    text += line;
  }
  return text;
}

TEST(MobilityTrace, LinesAreWhatPrintfWritesOnEdgeValues) {
  // Halves of the sixth decimal (printf rounds the binary value, not the decimal one), zeros of
  // both signs, values that round up across a power of ten, and the largest finite double.
  const std::vector<Vec2> first = {
      {0.0, -0.0},
      {0.0000005, 0.0000015},
      {0.0000025, -0.0000005},
      {999999.9999995, 9.9999995},
      {-123.4567895, 1e-7},
      {1e15 + 0.5, -1e-300},
      {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()},
      {3.0, 4.0}};
  std::vector<Vec2> second = first;
  second[0] = {0.1, 0.2};
  second[1] = {1.0000005, 2.5};
  second[4] = {-123.4567895, 1e-7};  // does not move: no line
  second[7] = {6.0, 8.0};
  std::ostringstream out;
  MobilityTraceWriter writer(out, 1, 0.1);
  writer.sample(0, first);
  writer.sample(1, second);
  EXPECT_EQ(out.str(), initial_lines(first) + setdest_lines(0.0, 0.1, first, second));
  EXPECT_NE(out.str().find("$ns_ at 0.000000 \"$node_(7) setdest 6.000000 8.000000 50.000000\"\n"),
            std::string::npos);
  EXPECT_EQ(out.str().find("$node_(4) setdest"), std::string::npos);
}

TEST(MobilityTrace, LinesAreWhatPrintfWritesOnRandomWalks) {
  std::mt19937_64 random(20261201);
  std::uniform_real_distribution<double> coordinate(-5000.0, 5000.0);
  std::uniform_real_distribution<double> move(-0.2, 0.2);
  std::vector<Vec2> positions(300);
  for (Vec2& p : positions) p = {coordinate(random), coordinate(random)};
  std::ostringstream out;
  const std::uint64_t interval = 3;
  const double step_s = 0.1;
  MobilityTraceWriter writer(out, interval, step_s);
  std::string expected;
  std::vector<Vec2> previous;
  std::uint64_t previous_step = 0;
  for (std::uint64_t step = 0; step < 31; ++step) {
    writer.sample(step, positions);
    if (step == 0) {
      expected += initial_lines(positions);
      previous = positions;
    } else if (step % interval == 0) {
      expected +=
          setdest_lines(static_cast<double>(previous_step) * step_s,
                        static_cast<double>(step - previous_step) * step_s, previous, positions);
      previous = positions;
      previous_step = step;
    }
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (i % 5 != 0) positions[i] += Vec2{move(random), move(random)};  // every fifth stands
    }
  }
  EXPECT_EQ(out.str(), expected);
  EXPECT_GT(out.str().size(), 100'000U);
}

}  // namespace
}  // namespace swarmnet
