#include "common/fem/quadrature.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace mortar {

SegmentRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: need n >= 1, got " + std::to_string(n));
  gsl_set_error_handler_off();  // report failures through return values, never abort
  std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)>
      table(gsl_integration_glfixed_table_alloc(static_cast<size_t>(n)),
            &gsl_integration_glfixed_table_free);
  if (!table) throw std::runtime_error("gauss_legendre: GSL could not build the " +
                                       std::to_string(n) + "-point table");
  SegmentRule rule;
  for (int i = 0; i < n; ++i) {
    double x = 0, w = 0;
    const int status = gsl_integration_glfixed_point(0.0, 1.0, static_cast<size_t>(i), &x, &w,
                                                     table.get());
    if (status != GSL_SUCCESS)
      throw std::runtime_error(std::string("gauss_legendre: ") + gsl_strerror(status));
    rule.points.push_back(x);
    rule.weights.push_back(w);
  }
  return rule;
}

TriangleRule triangle_rule(int degree) {
  if (degree < 0) throw std::invalid_argument("triangle_rule: negative degree " + std::to_string(degree));
  const int n = (degree + 3) / 2;  // smallest n with 2n - 2 >= degree
  const SegmentRule g = gauss_legendre(n);
  TriangleRule rule;
  rule.degree = 2 * n - 2;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = g.points[i], b = g.points[j];
      rule.points.emplace_back(a, b * (1.0 - a));
      // reference area 1/2 is scaled to 1: weight = 2 * (1 - a) * w_i * w_j
      rule.weights.push_back(2.0 * (1.0 - a) * g.weights[i] * g.weights[j]);
    }
  return rule;
}

}  // namespace mortar
