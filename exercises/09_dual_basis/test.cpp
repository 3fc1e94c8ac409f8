#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "common/interface/dual_basis.hpp"
#include "exercise.hpp"

namespace {
const double lengths[] = {1e-3, 0.25, 1.0, 3.7, 40.0};
const double covered[] = {1.0, 0.75, 0.5, 0.25, 0.1};

// 3-point Gauss-Legendre on [0, 1]: exact up to degree 5, so for the quadratic psi_k phi_l.
const double r = std::sqrt(0.15);
const double points[3] = {0.5 - r, 0.5, 0.5 + r};
const double weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};

// int_0^theta f(s) h ds for a polynomial f of degree 5 or less
template <class F>
double covered_integral(double h, double theta, F&& f) {
  double sum = 0;
  for (int q = 0; q < 3; ++q) sum += weights[q] * theta * h * f(theta * points[q]);
  return sum;
}
}  // namespace

TEST(DualElement, is_biorthogonal_to_the_hats_on_the_covered_part) {
  for (double h : lengths)
    for (double theta : covered) {
      const Eigen::Matrix2d A = exercise::dual_element_coefficients(h, theta);
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) {
          const auto phi = [](int m, double s) { return m == 0 ? 1 - s : s; };
          const double integral =
              covered_integral(h, theta, [&](double s) { return (A(k, 0) * phi(0, s) + A(k, 1) * phi(1, s)) * phi(l, s); });
          const double expected = k == l ? covered_integral(h, theta, [&](double s) { return phi(l, s); }) : 0.0;
          EXPECT_NEAR(integral, expected, 1e-12 * h) << "h = " << h << ", theta = " << theta << ": int psi_" << k
                                                     << " phi_" << l;
        }
    }
}

TEST(DualElement, is_the_librarys_basis_on_a_whole_element) {
  for (double h : lengths) {
    const Eigen::Matrix2d A = exercise::dual_element_coefficients(h, 1.0);
    const Eigen::Matrix2d reference = mortar::dual_element_coefficients(h);
    EXPECT_LT((A - reference).cwiseAbs().maxCoeff(), 1e-13) << "h = " << h << ", A_e =\n" << A;
  }
}

// Worked by hand for theta = 1/2, h = 2 (the library has no partly covered element): the
// covered mass matrix is h (7/24, 1/12; 1/12, 1/24), the weights h (3/8, 1/8).
TEST(DualElement, matches_a_case_worked_by_hand) {
  Eigen::Matrix2d expected;
  expected << 3, -6, -2, 7;
  const Eigen::Matrix2d A = exercise::dual_element_coefficients(2.0, 0.5);
  EXPECT_LT((A - expected).cwiseAbs().maxCoeff(), 1e-12) << "A_e =\n" << A;
}

TEST(DualElement, the_two_functions_sum_to_one) {
  for (double h : lengths)
    for (double theta : covered) {
      const Eigen::Matrix2d A = exercise::dual_element_coefficients(h, theta);
      for (double s : {0.0, 0.3, 0.5, 1.0}) {  // psi_a + psi_b at the ends and inside
        const double phi[2] = {1 - s, s};
        double sum = 0;
        for (int k = 0; k < 2; ++k) sum += A(k, 0) * phi[0] + A(k, 1) * phi[1];
        EXPECT_NEAR(sum, 1.0, 1e-11) << "h = " << h << ", theta = " << theta << ", s = " << s;
      }
    }
}

TEST(DualElement, refuses_an_empty_element_or_cover) {
  EXPECT_THROW(exercise::dual_element_coefficients(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(exercise::dual_element_coefficients(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(exercise::dual_element_coefficients(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(exercise::dual_element_coefficients(1.0, 1.5), std::invalid_argument);
}
