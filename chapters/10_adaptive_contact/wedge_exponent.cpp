#include "wedge_exponent.hpp"

#include <cmath>

namespace chapter10 {

double dundurs_alpha(double E1, double nu1, double E2, double nu2) {
  const double s1 = E1 / (1 - nu1 * nu1), s2 = E2 / (1 - nu2 * nu2);
  return (s1 - s2) / (s1 + s2);
}

namespace {
double characteristic(double lambda, double alpha, double phi) {
  const double pi = std::acos(-1.0), s = std::sin(lambda * phi), sp = std::sin(phi);
  return (1 - alpha) * (std::sin(2 * lambda * phi) + lambda * std::sin(2 * phi)) * std::sin(lambda * pi) +
         2 * (1 + alpha) * std::cos(lambda * pi) * (s * s - lambda * lambda * sp * sp);
}
}  // namespace

double wedge_on_half_plane_exponent(double alpha, double phi) {
  // the first sign change from the left (lambda = 1 is always a root: the regular term)
  constexpr int n = 4000;
  double lo = 1e-4, f_lo = characteristic(lo, alpha, phi);
  for (int k = 1; k <= n; ++k) {
    const double hi = 1e-4 + (1 - 2e-4) * k / n, f_hi = characteristic(hi, alpha, phi);
    if (f_lo * f_hi <= 0) {
      double a = lo, b = hi, fa = f_lo;
      for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
        const double m = 0.5 * (a + b), fm = characteristic(m, alpha, phi);
        if (fa * fm <= 0) b = m;
        else { a = m; fa = fm; }
      }
      return 0.5 * (a + b);
    }
    lo = hi;
    f_lo = f_hi;
  }
  return 1.0;
}

}  // namespace chapter10
