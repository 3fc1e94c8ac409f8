#include "exercise.hpp"

namespace exercise {

Eigen::Matrix2d dual_element_coefficients(double h) {
  Eigen::Matrix2d mass;  // M_e(k, l) = int_e phi_k phi_l
  mass << h / 3, h / 6, h / 6, h / 3;
  Eigen::Matrix2d lumped = Eigen::Matrix2d::Zero();  // D_e = diag(int_e phi_a, int_e phi_b)
  lumped(0, 0) = h / 2;
  lumped(1, 1) = h / 2;
  // int_e psi_k phi_l = (A_e M_e)(k, l) must equal D_e(k, l)
  return lumped * mass.inverse();
}

}  // namespace exercise
