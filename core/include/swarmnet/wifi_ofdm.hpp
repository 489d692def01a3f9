// IEEE 802.11a OFDM (clause 17) PHY facts shared by the kernel's PHY and 802.11 MAC plugins:
// the eight rates 6..54 Mbit/s with their modulation and coding, and frame durations.
//
// A frame on the air is a 16 us preamble, a 4 us PLCP header (SIGNAL field, one OFDM symbol at
// 6 Mbit/s), then the DATA field: SERVICE (16 bits) + PSDU (8 * bytes) + tail (6 bits), padded
// to whole 4 us symbols of N_DBPS = rate * 4 us data bits each.
#pragma once

#include <cstdint>
#include <optional>

#include "swarmnet/units.hpp"

namespace swarmnet::ofdm {

inline constexpr SimTime kPreambleDuration{16000};
inline constexpr SimTime kHeaderDuration{4000};
inline constexpr SimTime kSymbolDuration{4000};
inline constexpr double kHeaderRateBps = 6.0e6;
inline constexpr std::uint32_t kServiceBits = 16;
inline constexpr std::uint32_t kTailBits = 6;

enum class Modulation : std::uint8_t { bpsk, qpsk, qam16, qam64 };
enum class CodeRate : std::uint8_t { half, two_thirds, three_quarters };

struct Mode {
  double rate_bps;
  Modulation modulation;
  CodeRate code_rate;
  std::uint32_t data_bits_per_symbol;  // N_DBPS
};

inline constexpr Mode kModes[] = {
    {6.0e6, Modulation::bpsk, CodeRate::half, 24},
    {9.0e6, Modulation::bpsk, CodeRate::three_quarters, 36},
    {12.0e6, Modulation::qpsk, CodeRate::half, 48},
    {18.0e6, Modulation::qpsk, CodeRate::three_quarters, 72},
    {24.0e6, Modulation::qam16, CodeRate::half, 96},
    {36.0e6, Modulation::qam16, CodeRate::three_quarters, 144},
    {48.0e6, Modulation::qam64, CodeRate::two_thirds, 192},
    {54.0e6, Modulation::qam64, CodeRate::three_quarters, 216},
};

// The 802.11a mode of exactly this rate, if there is one.
inline std::optional<Mode> exact_mode(double rate_bps) {
  for (const Mode& mode : kModes) {
    if (mode.rate_bps == rate_bps) return mode;
  }
  return std::nullopt;
}

// The fastest 802.11a mode not faster than `rate_bps` (6 Mbit/s below that): how the PHY reads a
// frame whose MAC chose a rate that is not an 802.11a rate.
inline Mode mode_at_most(double rate_bps) {
  Mode chosen = kModes[0];
  for (const Mode& mode : kModes) {
    if (mode.rate_bps <= rate_bps) chosen = mode;
  }
  return chosen;
}

// Time on the air of a PSDU of `bytes` (MAC header, body and FCS) sent at `mode`.
inline SimTime frame_duration(std::uint32_t bytes, const Mode& mode) {
  const std::uint64_t bits = kServiceBits + 8ULL * bytes + kTailBits;
  const std::uint64_t symbols = (bits + mode.data_bits_per_symbol - 1) / mode.data_bits_per_symbol;
  return kPreambleDuration + kHeaderDuration + kSymbolDuration * static_cast<std::int64_t>(symbols);
}

}  // namespace swarmnet::ofdm
