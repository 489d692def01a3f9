#include "network/nist_error_rate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace swarmnet {

namespace {

double uncoded_ber(ofdm::Modulation modulation, double sinr) {
  switch (modulation) {
    case ofdm::Modulation::bpsk:
      return 0.5 * std::erfc(std::sqrt(sinr));
    case ofdm::Modulation::qpsk:
      return 0.5 * std::erfc(std::sqrt(sinr / 2.0));
    case ofdm::Modulation::qam16:
      return 0.75 * 0.5 * std::erfc(std::sqrt(sinr / 10.0));
    case ofdm::Modulation::qam64:
      return 7.0 / 12.0 * 0.5 * std::erfc(std::sqrt(sinr / 42.0));
  }
  return 1.0;
}

// Horner's rule for weights[0] + weights[1] x + weights[2] x^2 + ...: one multiply-add per term
// instead of a pow() each (the error model runs for every chunk of every reception).
template <std::size_t N>
double polynomial(const std::array<double, N>& weights, double x) {
  double sum = 0.0;
  for (std::size_t i = N; i-- > 0;) sum = sum * x + weights[i];
  return sum;
}

// Union bound on the coded bit error probability: sum over distances d of c_d * D^d, with
// D = sqrt(4 p (1 - p)) (Bhattacharyya parameter of hard decisions at raw error rate p).
double coded_ber(ofdm::CodeRate rate, double p) {
  const double d = std::sqrt(4.0 * p * (1.0 - p));
  const double d2 = d * d;
  const double d4 = d2 * d2;
  switch (rate) {
    case ofdm::CodeRate::half: {
      // Free distance 10; only even distances have paths: D^10 (c_10 + c_12 D^2 + ...).
      static constexpr std::array<double, 9> kWeights{
          36.0, 211.0, 1404.0, 11633.0, 77433.0, 502690.0, 3322763.0, 21292910.0, 134365911.0};
      return 0.5 * (d4 * d4 * d2) * polynomial(kWeights, d2);
    }
    case ofdm::CodeRate::two_thirds: {
      // Free distance 6.
      static constexpr std::array<double, 10> kWeights{
          3.0, 70.0, 285.0, 1276.0, 6160.0, 27128.0, 117019.0, 498860.0, 2103891.0, 8784123.0};
      return 1.0 / 4.0 * (d4 * d2) * polynomial(kWeights, d);
    }
    case ofdm::CodeRate::three_quarters: {
      // Free distance 5.
      static constexpr std::array<double, 10> kWeights{
          42.0,     201.0,     1492.0,     10469.0,    62935.0,
          379644.0, 2253373.0, 13073811.0, 75152755.0, 428005675.0};
      return 1.0 / 6.0 * (d4 * d) * polynomial(kWeights, d);
    }
  }
  return 1.0;
}

double coded_error(const ofdm::Mode& mode, double sinr) {
  const double ber = uncoded_ber(mode.modulation, sinr);
  if (ber == 0.0) return 0.0;
  return std::min(coded_ber(mode.code_rate, ber), 1.0);
}

// A coded error probability this small leaves 1 - pe == 1.0 in double precision (its spacing
// below 1 is 1.1e-16), whatever the number of bits.
constexpr double kNegligibleError = 1.0e-30;

double find_certain_success_sinr(const ofdm::Mode& mode) {
  double low = 0.0;
  double high = 1.0;
  while (coded_error(mode, high) >= kNegligibleError) high *= 2.0;
  for (int i = 0; i < 200 && high - low > 1.0e-9 * high; ++i) {
    const double middle = 0.5 * (low + high);
    (coded_error(mode, middle) >= kNegligibleError ? low : high) = middle;
  }
  // 3 dB of margin: far from where rounding in erfc or the series could matter.
  return 2.0 * high;
}

}  // namespace

double certain_success_sinr(const ofdm::Mode& mode) {
  // Once per (modulation, code rate): the error model depends on nothing else.
  static const auto thresholds = [] {
    std::array<std::array<double, 3>, 4> table{};
    for (std::size_t m = 0; m < table.size(); ++m) {
      for (std::size_t r = 0; r < table[m].size(); ++r) {
        ofdm::Mode combination{};
        combination.modulation = static_cast<ofdm::Modulation>(m);
        combination.code_rate = static_cast<ofdm::CodeRate>(r);
        table[m][r] = find_certain_success_sinr(combination);
      }
    }
    return table;
  }();
  return thresholds[static_cast<std::size_t>(mode.modulation)]
                   [static_cast<std::size_t>(mode.code_rate)];
}

double chunk_success_rate(const ofdm::Mode& mode, double sinr, double bits) {
  if (bits <= 0.0) return 1.0;
  // Most chunks of a reception near its sender are here: the formula below would give exactly 1.
  if (sinr >= certain_success_sinr(mode)) return 1.0;
  return std::pow(1.0 - coded_error(mode, sinr), bits);
}

}  // namespace swarmnet
