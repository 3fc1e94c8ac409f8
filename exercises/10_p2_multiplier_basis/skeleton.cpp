#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1, bool linear_first, bool linear_last) {
  // Your code here: refuse what the header says; then one row per node whose value stays free,
  // in order along Gamma_c, and whatever the linear end elements ask of the others.
  (void)linear_first;
  (void)linear_last;
  const int N = trace1.num_elements();
  return Eigen::MatrixXd::Zero(2 * N - 1, 2 * N + 1);
}

}  // namespace exercise
