// A confidence interval for the mean of values that lie in [0, 1] (a delivery ratio per run)
// that stays in [0, 1]. The Student-t interval mean ± t·sd/√n does not: runs with ratios 0.98,
// 0.99 and 1.0 give an upper bound above 1.
//
// Wilson's score interval with an effective sample size (the design-effect form used for survey
// proportions, Korn & Graubard 1998): the mean p is treated as a proportion whose variance is the
// observed variance of the mean, so n_eff = p(1 - p) / (sd² / n), and
//
//   centre = (p + z²/(2 n_eff)) / (1 + z²/n_eff)
//   half   = z / (1 + z²/n_eff) · sqrt(p(1 - p)/n_eff + z²/(4 n_eff²))
//
// with z the Student-t quantile for n - 1 degrees of freedom (so that small samples stay wide).
// The interval always lies in [0, 1]; values that are all equal give [p, p], as the t interval.
#pragma once

#include <span>

#include "stats/sample_statistics.hpp"

namespace swarmnet::stats {

// As summarize(), with ci_low and ci_high from the interval above (ci_half is half their
// distance). Values must lie in [0, 1].
SampleSummary summarize_proportions(std::span<const double> values, double confidence = 0.95);

}  // namespace swarmnet::stats
