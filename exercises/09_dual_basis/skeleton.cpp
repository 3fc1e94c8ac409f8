#include "exercise.hpp"

namespace exercise {

Eigen::Matrix2d dual_element_coefficients(double h) {
  // Your code here: the element mass matrix M_e = (int_e phi_k phi_l), the diagonal
  // D_e = diag(int_e phi_a, int_e phi_b), then A_e from A_e M_e = D_e. The identity below
  // gives back the hats themselves, which are not biorthogonal.
  (void)h;
  return Eigen::Matrix2d::Identity();
}

}  // namespace exercise
