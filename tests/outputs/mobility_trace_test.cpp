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
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMax = std::numeric_limits<double>::max();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Exact binary ties of the sixth decimal (printf rounds them to even), values that carry
  // across a power of ten, zeros of both signs, the largest doubles, infinities and NaNs.
  const std::vector<Vec2> first = {{0.0078125, 0.0234375},
                                   {0.0, -0.0},
                                   {9.9999996, 999999.9999996},
                                   {-0.0000005, 0.0000015},
                                   {1e15 + 0.5, -1e-300},
                                   {kMax, -kMax},
                                   {kInf, -kInf},
                                   {nan, -nan},
                                   {-123.4567895, 1e-7},
                                   {3.0, 4.0}};
  // Every node moves but one, so that each value passes through the setdest lines too.
  std::vector<Vec2> second(first.rbegin(), first.rend());
  second[8] = first[8];  // node 8 stays put: no line
  std::ostringstream out;
  MobilityTraceWriter writer(out, 1, 0.1);
  writer.sample(0, first);
  writer.sample(1, second);
  const std::string text = out.str();
  EXPECT_EQ(text, initial_lines(first) + setdest_lines(0.0, 0.1, first, second));
  for (const char* expected : {"$node_(0) set X_ 0.007812\n", "$node_(0) set Y_ 0.023438\n",
                               "$node_(1) set Y_ -0.000000\n", "$node_(2) set X_ 10.000000\n",
                               "$node_(2) set Y_ 1000000.000000\n", "$node_(6) set X_ inf\n",
                               "\"$node_(0) setdest 3.000000 4.000000 "}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
  EXPECT_EQ(text.find("$node_(8) setdest"), std::string::npos);
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
