// Exercise 9: the dual (biorthogonal) basis of the multiplier space on one element, biorthogonal
// on the part of it that the mortar side covers.
#pragma once

#include <Eigen/Dense>

namespace exercise {

// For one element of length h > 0 with local hats phi_a = 1 - s and phi_b = s (s = (x - x_a) / h),
// of which the mortar side covers 0 <= s <= theta (0 < theta <= 1): the 2 x 2 matrix A_e whose
// row k holds the dual function psi_k = A_e(k, 0) phi_a + A_e(k, 1) phi_b, such that
// int psi_k phi_l = delta_kl int phi_l, both integrals over the covered part. Throws
// std::invalid_argument for h <= 0 or theta outside (0, 1].
Eigen::Matrix2d dual_element_coefficients(double h, double theta);

}  // namespace exercise
