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

// Rounds to the nearest nanosecond, half away from zero, exactly as std::llround: written out
// because the library call was a measurable share of computing every link's delay.
inline SimTime from_seconds(double seconds) {
  const double ns = seconds * 1e9;
  // From 2^52 on every double is whole; there, and for NaN or overflow, llround's own answer.
  if (!(std::fabs(ns) < 0x1p52)) return SimTime{static_cast<std::int64_t>(std::llround(ns))};
  const auto whole = static_cast<std::int64_t>(ns);         // toward zero
  const double fraction = ns - static_cast<double>(whole);  // exact below 2^52
  if (fraction >= 0.5) return SimTime{whole + 1};
  if (fraction <= -0.5) return SimTime{whole - 1};
  return SimTime{whole};
}
inline constexpr double to_seconds(SimTime t) { return static_cast<double>(t.count()) * 1e-9; }

inline constexpr double kSpeedOfLightMps = 299792458.0;

inline double dbm_to_milliwatts(double dbm) { return std::pow(10.0, dbm / 10.0); }
inline double milliwatts_to_dbm(double mw) { return 10.0 * std::log10(mw); }

}  // namespace swarmnet
