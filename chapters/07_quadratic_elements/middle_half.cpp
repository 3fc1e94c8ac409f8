#include "middle_half.hpp"

#include <algorithm>
#include <cmath>

#include "common/contact/pressure_norms.hpp"
#include "common/fem/quadrature.hpp"

namespace chapter07 {

void add_middle_half_errors(const mortar::BilateralLevel& level, const mortar::ManufacturedContact& exact,
                            mortar::Row& row) {
  const mortar::ContactInterface& gamma = level.solution.gamma;
  const mortar::InterfaceTrace& t = gamma.nonmortar_trace;
  const auto p = [&](double x) { return exact.pressure(x); };
  const mortar::InterfaceCurve best = mortar::l2_projection(gamma, p);
  // Gauss on each element: lambda_h and Pi_h p are quadratic there, p smooth
  const mortar::SegmentRule g = mortar::gauss_legendre(6);
  const double a = t.x.front() + 0.25 * t.length(), b = t.x.front() + 0.75 * t.length();
  const double tol = 1e-12 * t.length();
  double computed = 0, projected = 0, means = 0;
  for (int e = 0; e < t.num_elements(); ++e) {
    // the part of element e inside [a, b]: the L2 norms cut the elements at L/4 and 3L/4
    const double h = t.x[e + 1] - t.x[e], lo = std::max(t.x[e], a), hi = std::min(t.x[e + 1], b);
    if (!(hi > lo)) continue;
    double integral = 0;  // int (lambda_h - p) over that part
    for (std::size_t k = 0; k < g.points.size(); ++k) {
      const double x = lo + g.points[k] * (hi - lo), w = g.weights[k] * (hi - lo), s = (x - t.x[e]) / h;
      const double d = level.pressure.at(e, s) - p(x), d_best = best.at(e, s) - p(x);
      computed += w * d * d;
      projected += w * d_best * d_best;
      integral += w * d;
    }
    // the means over whole elements only: a cut element's mean would be of another length
    if (lo <= t.x[e] + tol && hi >= t.x[e + 1] - tol) means += integral * integral / h;
  }
  const double norm = level.pressure_errors.norm_l2;
  row.emplace_back("err_pressure_middle", std::sqrt(computed) / norm);
  row.emplace_back("err_pressure_best_middle", std::sqrt(projected) / norm);
  row.emplace_back("err_pressure_means_middle", std::sqrt(means) / norm);
}

}  // namespace chapter07
