#include <gtest/gtest.h>

#include <cmath>

#include "common/interface/dual_basis.hpp"
#include "exercise.hpp"

namespace {
const double lengths[] = {1e-3, 0.25, 1.0, 3.7, 40.0};

// 3-point Gauss-Legendre on [0, 1]: exact up to degree 5, so for the quadratic psi_k phi_l.
const double r = std::sqrt(0.15);
const double points[3] = {0.5 - r, 0.5, 0.5 + r};
const double weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
}  // namespace

TEST(DualElement, is_biorthogonal_to_the_hats) {
  for (double h : lengths) {
    const Eigen::Matrix2d A = exercise::dual_element_coefficients(h);
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 2; ++l) {
        double integral = 0;  // int_e psi_k phi_l on an element of length h
        for (int q = 0; q < 3; ++q) {
          const double s = points[q], phi[2] = {1 - s, s};
          integral += weights[q] * h * (A(k, 0) * phi[0] + A(k, 1) * phi[1]) * phi[l];
        }
        EXPECT_NEAR(integral, k == l ? h / 2 : 0.0, 1e-14 * h)
            << "h = " << h << ": int psi_" << k << " phi_" << l;
      }
  }
}

TEST(DualElement, equals_the_library_coefficients) {
  for (double h : lengths) {
    const Eigen::Matrix2d A = exercise::dual_element_coefficients(h);
    const Eigen::Matrix2d reference = mortar::dual_element_coefficients(h);
    EXPECT_LT((A - reference).cwiseAbs().maxCoeff(), 1e-13) << "h = " << h << ", A_e =\n" << A;
  }
}

TEST(DualElement, the_two_functions_sum_to_one) {
  for (double h : lengths) {
    const Eigen::Matrix2d A = exercise::dual_element_coefficients(h);
    // psi_a + psi_b at the ends and inside the element
    for (double s : {0.0, 0.3, 0.5, 1.0}) {
      const double phi[2] = {1 - s, s};
      double sum = 0;
      for (int k = 0; k < 2; ++k) sum += A(k, 0) * phi[0] + A(k, 1) * phi[1];
      EXPECT_NEAR(sum, 1.0, 1e-14) << "h = " << h << ", s = " << s;
    }
  }
}
