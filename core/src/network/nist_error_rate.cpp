#include "network/nist_error_rate.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

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

// Union bound on the coded bit error probability: sum over distances d of c_d * D^d, with
// D = sqrt(4 p (1 - p)) (Bhattacharyya parameter of hard decisions at raw error rate p).
double coded_ber(ofdm::CodeRate rate, double p) {
  const double d = std::sqrt(4.0 * p * (1.0 - p));
  const auto series = [d](int first_power, std::initializer_list<double> weights) {
    double sum = 0.0;
    int power = first_power;
    for (const double weight : weights) sum += weight * std::pow(d, power++);
    return sum;
  };
  switch (rate) {
    case ofdm::CodeRate::half: {
      // Free distance 10; only even distances have paths.
      const double weights[] = {36.0,     211.0,     1404.0,     11633.0,    77433.0,
                                502690.0, 3322763.0, 21292910.0, 134365911.0};
      double sum = 0.0;
      int power = 10;
      for (const double weight : weights) {
        sum += weight * std::pow(d, power);
        power += 2;
      }
      return 0.5 * sum;
    }
    case ofdm::CodeRate::two_thirds:
      return 1.0 / 4.0 *
             series(6, {3.0, 70.0, 285.0, 1276.0, 6160.0, 27128.0, 117019.0, 498860.0, 2103891.0,
                        8784123.0});
    case ofdm::CodeRate::three_quarters:
      return 1.0 / 6.0 *
             series(5, {42.0, 201.0, 1492.0, 10469.0, 62935.0, 379644.0, 2253373.0, 13073811.0,
                        75152755.0, 428005675.0});
  }
  return 1.0;
}

}  // namespace

double chunk_success_rate(const ofdm::Mode& mode, double sinr, double bits) {
  if (bits <= 0.0) return 1.0;
  const double ber = uncoded_ber(mode.modulation, sinr);
  if (ber == 0.0) return 1.0;
  const double pe = std::min(coded_ber(mode.code_rate, ber), 1.0);
  return std::pow(1.0 - pe, bits);
}

}  // namespace swarmnet
