#include "stats/sample_statistics.hpp"

#include <cmath>
#include <limits>

#include "stats/student_t.hpp"

namespace swarmnet::stats {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Moments {
  double mean = kNaN;
  double variance = kNaN;  // unbiased
};

Moments moments(std::span<const double> values) {
  Moments m;
  if (values.empty()) return m;
  double sum = 0.0;
  for (const double v : values) sum += v;
  m.mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return m;
  double squares = 0.0;
  for (const double v : values) squares += (v - m.mean) * (v - m.mean);
  m.variance = squares / static_cast<double>(values.size() - 1);
  return m;
}

}  // namespace

SampleSummary summarize(std::span<const double> values, double confidence) {
  SampleSummary s;
  s.n = values.size();
  const Moments m = moments(values);
  s.mean = m.mean;
  s.sd = std::sqrt(m.variance);
  if (s.n >= 2) {
    const double n = static_cast<double>(s.n);
    s.ci_half = student_t_quantile(0.5 + confidence / 2.0, n - 1.0) * s.sd / std::sqrt(n);
  } else {
    s.ci_half = kNaN;
  }
  s.ci_low = s.mean - s.ci_half;
  s.ci_high = s.mean + s.ci_half;
  return s;
}

WelchTest welch_test(std::span<const double> a, std::span<const double> b) {
  WelchTest w{kNaN, kNaN, kNaN};
  if (a.size() < 2 || b.size() < 2) return w;
  const Moments ma = moments(a);
  const Moments mb = moments(b);
  const double va = ma.variance / static_cast<double>(a.size());
  const double vb = mb.variance / static_cast<double>(b.size());
  if (va + vb == 0.0) return w;
  w.t = (ma.mean - mb.mean) / std::sqrt(va + vb);
  w.df =
      (va + vb) * (va + vb) /
      (va * va / static_cast<double>(a.size() - 1) + vb * vb / static_cast<double>(b.size() - 1));
  w.p = student_t_two_sided_p(w.t, w.df);
  return w;
}

}  // namespace swarmnet::stats
