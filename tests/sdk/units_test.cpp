// The SDK's unit conversions.
#include "swarmnet/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "swarmnet/random.hpp"

namespace swarmnet {
namespace {

std::int64_t library_rounding(double seconds) { return std::llround(seconds * 1e9); }

TEST(SdkUnits, FromSecondsRoundsAsLlroundOnTheEdges) {
  std::vector<double> nanoseconds = {0.0,
                                     -0.0,
                                     0.5,
                                     -0.5,
                                     1.5,
                                     -1.5,
                                     2.5,
                                     -2.5,
                                     0.49999999999999994,
                                     -0.49999999999999994,
                                     1e15 + 0.5,
                                     0x1p52 - 0.5,
                                     0x1p52,
                                     -0x1p52,
                                     0x1p53 + 2.0,
                                     9.2e18,
                                     -9.2e18};
  for (double ns = 0.5; ns < 1e12; ns = ns * 3.0 + 0.5) {
    nanoseconds.push_back(ns);
    nanoseconds.push_back(-ns);
    nanoseconds.push_back(std::nextafter(ns, 0.0));
    nanoseconds.push_back(std::nextafter(ns, ns * 2.0));
  }
  for (const double ns : nanoseconds) {
    const double seconds = ns / 1e9;
    EXPECT_EQ(from_seconds(seconds).count(), library_rounding(seconds)) << ns << " ns";
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
