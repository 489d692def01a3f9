#include "stats/student_t.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace swarmnet::stats {

namespace {

// The continued fraction of I_x(a, b) (without its prefactor), by the modified Lentz method.
double beta_continued_fraction(double x, double a, double b) {
  constexpr int kMaxTerms = 10000;
  constexpr double kEpsilon = 1e-16;
  constexpr double kTiny = 1e-300;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double fraction = d;
  for (int m = 1; m <= kMaxTerms; ++m) {
    const double md = m;
    // Even term d_{2m}.
    double term = md * (b - md) * x / ((a + 2.0 * md - 1.0) * (a + 2.0 * md));
    d = 1.0 + term * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + term / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    fraction *= d * c;
    // Odd term d_{2m+1}.
    term = -(a + md) * (a + b + md) * x / ((a + 2.0 * md) * (a + 2.0 * md + 1.0));
    d = 1.0 + term * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = 1.0 + term / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double change = d * c;
    fraction *= change;
    if (std::fabs(change - 1.0) < kEpsilon) return fraction;
  }
  throw std::runtime_error("incomplete beta: continued fraction did not converge");
}

}  // namespace

double incomplete_beta(double x, double a, double b) {
  if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0) || !(x <= 1.0)) {
    throw std::invalid_argument("incomplete beta: needs a > 0, b > 0 and 0 <= x <= 1");
  }
  if (x == 0.0 || x == 1.0) return x;
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  const double front = std::exp(log_front);
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_continued_fraction(x, a, b) / a;
  return 1.0 - front * beta_continued_fraction(1.0 - x, b, a) / b;
}

double student_t_two_sided_p(double t, double df) {
  if (!(df > 0.0)) throw std::invalid_argument("t distribution: degrees of freedom must be > 0");
  if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(t)) return 0.0;
  return incomplete_beta(df / (df + t * t), df / 2.0, 0.5);
}

double student_t_cdf(double t, double df) {
  const double tail = student_t_two_sided_p(t, df) / 2.0;
  return t >= 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double df) {
  if (!(p > 0.0) || !(p < 1.0)) throw std::invalid_argument("t quantile: needs 0 < p < 1");
  if (p == 0.5) return 0.0;
  // Bracket the quantile, then bisect until the interval stops shrinking.
  double low = 0.0;
  double high = 1.0;
  const double target = p > 0.5 ? p : 1.0 - p;
  while (student_t_cdf(high, df) < target) {
    low = high;
    high *= 2.0;
  }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    if (mid <= low || mid >= high) break;
    if (student_t_cdf(mid, df) < target) {
      low = mid;
    } else {
      high = mid;
    }
  }
  const double q = 0.5 * (low + high);
  return p > 0.5 ? q : -q;
}

}  // namespace swarmnet::stats
