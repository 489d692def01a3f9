// The OFDM error-rate model of ns-3's NistErrorRateModel (G. Pei and T. Henderson, "Validation
// of OFDM error rate model in ns-3", Boeing, 2010), the default of ns-3's YansWifiPhy.
//
// Why this model: SwarmNet is validated against ns-3 (DESIGN.md, issue 4 part 5), so frame
// success must follow the same curve. Uncoded bit error rate of the modulation at SNR s (linear):
//   BPSK 0.5 erfc(sqrt(s)), QPSK 0.5 erfc(sqrt(s/2)), 16-QAM 0.75 * 0.5 erfc(sqrt(s/10)),
//   64-QAM 7/12 * 0.5 erfc(sqrt(s/42));
// then the union bound of the convolutional code (rate 1/2, 2/3 or 3/4 with its distance
// spectrum) gives the coded bit error probability pe, and n bits survive with (1 - pe)^n.
#pragma once

#include <cstdint>

#include "swarmnet/wifi_ofdm.hpp"

namespace swarmnet {

// Probability that `bits` bits sent at `mode` are all received correctly at linear SINR `sinr`.
double chunk_success_rate(const ofdm::Mode& mode, double sinr, double bits);

// The linear SINR from which chunk_success_rate is exactly 1 for any number of bits (the coded
// error probability is below 1e-30, and 1 - pe rounds to 1), with 3 dB of margin: 14.2 dB for BPSK
// 1/2. chunk_success_rate returns 1 there without evaluating the series.
double certain_success_sinr(const ofdm::Mode& mode);

}  // namespace swarmnet
