// Student's t distribution, from the regularised incomplete beta function (evaluated by its
// continued fraction with the modified Lentz method), written from the mathematics:
//
//   I_x(a, b) = x^a (1-x)^b / (a B(a, b)) * 1/(1+ d1/(1+ d2/(1+ ...)))
//     d_{2m+1} = -(a+m)(a+b+m) x / ((a+2m)(a+2m+1)),  d_{2m} = m(b-m) x / ((a+2m-1)(a+2m))
//   used directly when x < (a+1)/(a+b+2), else through I_x(a, b) = 1 - I_{1-x}(b, a).
//
//   P(T <= t) for df degrees of freedom: 1 - I_{df/(df+t^2)}(df/2, 1/2) / 2 for t >= 0,
//   symmetric for t < 0. Degrees of freedom may be fractional (Welch's test).
#pragma once

namespace swarmnet::stats {

// Regularised incomplete beta I_x(a, b), a, b > 0, 0 <= x <= 1; accurate to about 1e-14.
double incomplete_beta(double x, double a, double b);

// P(T <= t) for Student's t with `df` > 0 degrees of freedom.
double student_t_cdf(double t, double df);

// The t with P(T <= t) = p, 0 < p < 1 (bisection on the CDF to full double precision).
double student_t_quantile(double p, double df);

// Two-sided p-value of an observed t: P(|T| >= |t|).
double student_t_two_sided_p(double t, double df);

}  // namespace swarmnet::stats
