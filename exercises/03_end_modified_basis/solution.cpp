#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd end_modified_basis(int N) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(N - 1, N + 1);
  for (int i = 1; i <= N - 1; ++i) C(i - 1, i) = 1.0;  // psi_i = phi_i at interior node i
  C(0, 0) = 1.0;                                       // psi_1 = phi_0 + phi_1
  C(N - 2, N) = 1.0;                                   // psi_{N-1} = phi_{N-1} + phi_N
  return C;
}

}  // namespace exercise
