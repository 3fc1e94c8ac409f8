#include "hertz.hpp"

#include <cmath>

namespace chapter05 {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double Hertz::half_width() const { return std::sqrt(4 * P * R / (pi * E_star)); }

double Hertz::peak_pressure() const {
  const double a = half_width();
  return a > 0 ? 2 * P / (pi * a) : 0.0;
}

double Hertz::pressure(double x) const {
  const double a = half_width();
  return std::fabs(x) < a ? peak_pressure() * std::sqrt(1 - x * x / (a * a)) : 0.0;
}

Hertz hertz_at_force(double E1, double nu1, double E2, double nu2, double R, double P) {
  Hertz h;
  h.E_star = 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
  h.R = R;
  h.P = P;
  return h;
}

}  // namespace chapter05
