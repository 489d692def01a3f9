// The SDK's unit conversions.
#include "swarmnet/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "swarmnet/random.hpp"

namespace swarmnet {
namespace {

std::int64_t library_rounding(double seconds) { return std::llround(seconds * 1e9); }

// Seconds whose product with 1e9 is exactly `ns`, if a neighbour of ns / 1e9 has one: an edge
// tested through ns / 1e9 alone may round away from the edge before from_seconds sees it.
std::optional<double> seconds_giving(double ns) {
  double seconds = ns / 1e9;
  for (int step = 0; step < 8; ++step) {
    const double product = seconds * 1e9;
    if (product == ns) return seconds;
    seconds = std::nextafter(seconds, product < ns ? INFINITY : -INFINITY);
  }
  return std::nullopt;
}

TEST(SdkUnits, FromSecondsRoundsHalvesAwayFromZero) {
  struct Case {
    double ns;
    std::int64_t rounded;
  };
  const std::vector<Case> cases = {{0.0, 0},
                                   {-0.0, 0},
                                   {0.5, 1},
                                   {-0.5, -1},
                                   {1.5, 2},
                                   {-1.5, -2},
                                   {2.5, 3},
                                   {-2.5, -3},
                                   {0.49999999999999994, 0},
                                   {-0.49999999999999994, 0},
                                   {2160.5, 2161},  // a link's delay at 648 m is about 2,161 ns
                                   {1e15 + 0.5, 1000000000000001},
                                   {0x1p52 - 0.5, 4503599627370496},
                                   {0x1p52, 4503599627370496},
                                   {-0x1p52, -4503599627370496}};
  for (const Case& c : cases) {
    const std::optional<double> seconds = seconds_giving(c.ns);
    ASSERT_TRUE(seconds.has_value()) << c.ns << " ns";
    EXPECT_EQ(from_seconds(*seconds).count(), c.rounded) << c.ns << " ns";
    EXPECT_EQ(from_seconds(*seconds).count(), library_rounding(*seconds)) << c.ns << " ns";
  }
}

TEST(SdkUnits, FromSecondsRoundsAsLlroundAroundEveryHalf) {
  // k + 0.5 and its two neighbours, for k across the whole range below 2^52, both signs.
  int exact = 0;
  for (double half = 0.5; half < 0x1p52; half = std::floor(half * 3.0) + 0.5) {
    for (const double ns : {half, std::nextafter(half, 0.0), std::nextafter(half, INFINITY)}) {
      for (const double signed_ns : {ns, -ns}) {
        const std::optional<double> seconds = seconds_giving(signed_ns);
        if (!seconds) continue;
        ++exact;
        EXPECT_EQ(from_seconds(*seconds).count(), library_rounding(*seconds)) << signed_ns;
      }
    }
  }
  EXPECT_GT(exact, 180);  // most edges are reachable exactly (194 of 204)
  // From 2^52 on every value is whole, and llround answers.
  for (const double ns : {0x1p52 + 1.0, 0x1p53 + 2.0, 9.2e18, -9.2e18}) {
    EXPECT_EQ(from_seconds(ns / 1e9).count(), library_rounding(ns / 1e9)) << ns;
  }
}

TEST(SdkUnits, FromSecondsRoundsAsLlroundOnRandomValues) {
  RandomStream random(5);
  for (int i = 0; i < 200000; ++i) {
    // Delays and durations of every size a run meets, both signs.
    const double seconds =
        std::ldexp(random.uniform(-1.0, 1.0), static_cast<int>(random.below(80)) - 50);
    ASSERT_EQ(from_seconds(seconds).count(), library_rounding(seconds)) << seconds << " s";
  }
}

}  // namespace
}  // namespace swarmnet
