// Simulated time and physical units shared by the kernel and every plugin.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>

namespace swarmnet {

// Simulated time is an integer count of nanoseconds: a run is a pure function of its inputs only
// if no floating-point rounding can reorder two events.
using SimTime = std::chrono::duration<std::int64_t, std::nano>;

inline constexpr SimTime kTimeZero{0};
inline constexpr SimTime kTimeNever{std::numeric_limits<std::int64_t>::max()};

// Rounds to the nearest nanosecond (half away from zero).
inline SimTime from_seconds(double seconds) {
  return SimTime{static_cast<std::int64_t>(std::llround(seconds * 1e9))};
}
inline constexpr double to_seconds(SimTime t) { return static_cast<double>(t.count()) * 1e-9; }

inline constexpr double kSpeedOfLightMps = 299792458.0;

inline double dbm_to_milliwatts(double dbm) { return std::pow(10.0, dbm / 10.0); }
inline double milliwatts_to_dbm(double mw) { return 10.0 * std::log10(mw); }

}  // namespace swarmnet
