#include "exercise.hpp"

#include <stdexcept>
#include <string>

namespace exercise {

Eigen::Matrix2d dual_element_coefficients(double h, double theta) {
  if (!(h > 0)) throw std::invalid_argument("dual_element_coefficients: h must be positive, got " + std::to_string(h));
  if (!(theta > 0 && theta <= 1))
    throw std::invalid_argument("dual_element_coefficients: theta must be in (0, 1], got " + std::to_string(theta));
  // The covered part's mass matrix, M(k, l) = int_0^theta phi_k phi_l h ds
  const double t = theta, t2 = t * t, t3 = t2 * t;
  Eigen::Matrix2d mass;
  mass << h * (t - t2 + t3 / 3), h * (t2 / 2 - t3 / 3),  //
      h * (t2 / 2 - t3 / 3), h * t3 / 3;
  // and D = diag(int_0^theta phi_a h ds, int_0^theta phi_b h ds), the row sums of M
  Eigen::Matrix2d weights = Eigen::Matrix2d::Zero();
  weights(0, 0) = h * (t - t2 / 2);
  weights(1, 1) = h * t2 / 2;
  // int psi_k phi_l = (A_e M)(k, l) must equal D(k, l)
  return weights * mass.inverse();
}

}  // namespace exercise
