// Holm's step-down correction for m tests at once (Holm 1979): sort the p-values ascending,
// p_(1) <= ... <= p_(m); the adjusted p_(i) is max over j <= i of min(1, (m - j + 1) p_(j)).
// Rejecting where an adjusted p is below alpha keeps the chance of any false rejection among
// the m tests below alpha, under any dependence between them; uniformly better than Bonferroni.
#pragma once

#include <vector>

namespace swarmnet::stats {

// The adjusted p-values, in the order given. NaN entries (a test that could not be computed)
// stay NaN and do not count in m.
std::vector<double> holm_adjust(const std::vector<double>& p);

}  // namespace swarmnet::stats
