#include "stats/proportion_interval.hpp"

#include <algorithm>
#include <cmath>

#include "stats/student_t.hpp"

namespace swarmnet::stats {

SampleSummary summarize_proportions(std::span<const double> values, double confidence) {
  SampleSummary s = summarize(values, confidence);
  if (s.n < 2 || !(s.sd > 0.0)) return s;  // undefined, or all equal: [p, p] already
  const double n = static_cast<double>(s.n);
  const double p = s.mean;
  const double variance_of_mean = s.sd * s.sd / n;
  const double n_eff = p * (1.0 - p) / variance_of_mean;
  const double z = student_t_quantile(0.5 + confidence / 2.0, n - 1.0);
  const double z2 = z * z;
  const double centre = (p + z2 / (2.0 * n_eff)) / (1.0 + z2 / n_eff);
  const double half =
      z / (1.0 + z2 / n_eff) * std::sqrt(p * (1.0 - p) / n_eff + z2 / (4.0 * n_eff * n_eff));
  // Rounding may step a hair outside [0, 1]; the interval is defined inside it.
  s.ci_low = std::clamp(centre - half, 0.0, 1.0);
  s.ci_high = std::clamp(centre + half, 0.0, 1.0);
  s.ci_half = (s.ci_high - s.ci_low) / 2.0;
  return s;
}

}  // namespace swarmnet::stats
