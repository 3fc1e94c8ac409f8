#include <gtest/gtest.h>

#include <cmath>

#include "common/fem/quadrature.hpp"

using namespace mortar;

namespace {
// int_0^1 x^k = 1 / (k + 1)
double segment_integral(const SegmentRule& r, int k) {
  double s = 0;
  for (size_t q = 0; q < r.points.size(); ++q) s += r.weights[q] * std::pow(r.points[q], k);
  return s;
}
// Average of s^i t^j over the reference triangle: 2 * i! j! / (i + j + 2)!
double triangle_average(const TriangleRule& r, int i, int j) {
  double s = 0;
  for (size_t q = 0; q < r.points.size(); ++q)
    s += r.weights[q] * std::pow(r.points[q].x(), i) * std::pow(r.points[q].y(), j);
  return s;
}
double exact_triangle_average(int i, int j) {
  return 2.0 * std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3);
}
}  // namespace

TEST(Quadrature, gauss_legendre_is_exact_to_degree_2n_minus_1) {
  for (int n = 1; n <= 6; ++n) {
    const SegmentRule r = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k)
      EXPECT_NEAR(segment_integral(r, k), 1.0 / (k + 1), 1e-14) << "n = " << n << ", x^" << k;
    // the stated degree is sharp: x^{2n} is not integrated exactly
    EXPECT_GT(std::fabs(segment_integral(r, 2 * n) - 1.0 / (2 * n + 1)), 1e-9) << "n = " << n;
  }
}

TEST(Quadrature, triangle_rule_is_exact_to_its_stated_degree) {
  for (int degree = 0; degree <= 8; ++degree) {
    const TriangleRule r = triangle_rule(degree);
    EXPECT_GE(r.degree, degree);
    for (int i = 0; i <= r.degree; ++i)
      for (int j = 0; i + j <= r.degree; ++j)
        EXPECT_NEAR(triangle_average(r, i, j), exact_triangle_average(i, j), 1e-14)
            << "rule of degree " << r.degree << ", s^" << i << " t^" << j;
    // and one degree more fails for some monomial
    double worst = 0;
    for (int i = 0; i <= r.degree + 1; ++i)
      worst = std::max(worst, std::fabs(triangle_average(r, i, r.degree + 1 - i) -
                                        exact_triangle_average(i, r.degree + 1 - i)));
    EXPECT_GT(worst, 1e-8) << "degree " << r.degree << " is not the sharp degree";
  }
}

TEST(Quadrature, rejects_bad_sizes) {
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(triangle_rule(-1), std::invalid_argument);
}
