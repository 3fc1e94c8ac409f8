#include <algorithm>
#include <cmath>
#include <vector>

#include "exercise.hpp"

namespace exercise {

namespace {

// 3-point Gauss-Legendre on [0, 1]: exact for degree 5, and the integrand P_gamma P_theta is of
// degree 4 when g is a cubic.
constexpr double gauss_x[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr double gauss_w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};

// The root of f in [lo, hi], where f changes sign: bisection to the last bit.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  double f_lo = f(lo);
  for (int k = 0; k < 200 && hi - lo > 1e-16 * std::max(1.0, std::fabs(lo)); ++k) {
    const double mid = 0.5 * (lo + hi), f_mid = f(mid);
    if ((f_mid > 0) == (f_lo > 0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

SegmentTerm nitsche_segment_term(const Segment& s, double theta, const std::function<double(double)>& gap,
                                 const Vector12& u) {
  const double L = s.b - s.a, g = s.gamma, pu = s.p.dot(u);
  const auto jump = [&](double x) -> Vector12 {
    const double t = (x - s.a) / L;
    return (1 - t) * s.jump_a + t * s.jump_b;
  };
  const auto P = [&](double x) { return pu + g * (jump(x).dot(u) - gap(x)); };
  // The pieces: P_gamma sampled on 64 sub-intervals, each sign change refined by bisection (a
  // smooth g has finitely many roots; a cubic at most three).
  std::vector<double> cuts = {s.a};
  const int n = 64;
  for (int k = 0; k < n; ++k) {
    const double lo = s.a + k * L / n, hi = s.a + (k + 1) * L / n;
    if ((P(lo) > 0) != (P(hi) > 0)) cuts.push_back(bisect(P, lo, hi));
  }
  cuts.push_back(s.b);
  SegmentTerm out;
  out.residual = -(theta / g) * L * pu * s.p;
  out.jacobian = -(theta / g) * L * s.p * s.p.transpose();
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    if (hi <= lo || P(0.5 * (lo + hi)) <= 0) continue;  // inactive piece
    for (int q = 0; q < 3; ++q) {
      const double x = lo + gauss_x[q] * (hi - lo), w = gauss_w[q] * (hi - lo);
      const Vector12 J = jump(x);
      const Vector12 test = theta * s.p + g * J, trial = s.p + g * J;
      out.residual += (w / g) * std::max(0.0, P(x)) * test;
      out.jacobian += (w / g) * test * trial.transpose();
    }
  }
  return out;
}

}  // namespace exercise
