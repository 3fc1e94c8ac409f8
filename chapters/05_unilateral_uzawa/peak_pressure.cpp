#include "peak_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/fem/quadrature.hpp"

namespace chapter05 {

namespace {
// alpha of the L2 fit alpha + beta (x - c)^2 of f over (c - w, c + w), the integrals taken
// piece by piece between the given breakpoints (f smooth on each piece).
double parabola_at_centre(const std::function<double(double)>& f, std::vector<double> breaks,
                          double c, double w) {
  breaks.push_back(c - w);
  breaks.push_back(c + w);
  std::sort(breaks.begin(), breaks.end());
  const mortar::SegmentRule g = mortar::gauss_legendre(8);
  double m0 = 0, m2 = 0, m4 = 0, f0 = 0, f2 = 0;  // int t^k and int f t^k, t = (x - c)^2
  for (std::size_t e = 0; e + 1 < breaks.size(); ++e) {
    const double lo = std::max(breaks[e], c - w), hi = std::min(breaks[e + 1], c + w);
    if (!(hi > lo)) continue;
    for (std::size_t q = 0; q < g.points.size(); ++q) {
      const double x = lo + g.points[q] * (hi - lo), weight = g.weights[q] * (hi - lo);
      const double t = (x - c) * (x - c), v = f(x);
      m0 += weight, m2 += weight * t, m4 += weight * t * t;
      f0 += weight * v, f2 += weight * v * t;
    }
  }
  // normal equations [m0 m2; m2 m4] (alpha, beta) = (f0, f2), solved for alpha
  return (f0 * m4 - f2 * m2) / (m0 * m4 - m2 * m2);
}

// What the fit gives for the unit ellipse sqrt(1 - x^2) over its central half: 1.00078.
double ellipse_factor() {
  return parabola_at_centre([](double x) { return std::sqrt(1 - x * x); }, {}, 0.0, 0.5);
}
}  // namespace

double pressure_at(const mortar::InterfaceCurve& p, double x) {
  if (p.x.empty()) return 0.0;
  const auto it = std::upper_bound(p.x.begin(), p.x.end(), x);
  const std::size_t e = std::clamp<std::size_t>(it - p.x.begin(), 1, p.x.size() - 1) - 1;
  const double s = std::clamp((x - p.x[e]) / (p.x[e + 1] - p.x[e]), 0.0, 1.0);
  return (1 - s) * p.value[e] + s * p.value[e + 1];
}

double peak_pressure(const mortar::InterfaceCurve& p, double c) {
  const mortar::ContactZone zone = mortar::contact_zone(p);
  if (zone.empty) return 0.0;
  const auto f = [&p](double x) { return pressure_at(p, x); };
  static const double factor = ellipse_factor();
  return parabola_at_centre(f, p.x, c, 0.5 * zone.half_width()) / factor;
}

}  // namespace chapter05
