// Exercise 9: the dual (biorthogonal) basis of the multiplier space on one element.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// For one element of length h > 0 with local hats phi_a = 1 - s and phi_b = s: the 2 x 2
// matrix A_e whose row k holds the dual function psi_k = A_e(k, 0) phi_a + A_e(k, 1) phi_b,
// such that int_e psi_k phi_l = delta_kl int_e phi_l (k, l in {a, b}).
Eigen::Matrix2d dual_element_coefficients(double h);

}  // namespace exercise
