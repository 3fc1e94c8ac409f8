#include <algorithm>

#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd end_modified_basis(int N, bool constant_first, bool constant_last) {
  // Your code here: refuse what the header says; then one row per free nodal value, in order
  // along Gamma_c, and whatever the constant end elements ask of the other nodes.
  (void)constant_first;
  (void)constant_last;
  return Eigen::MatrixXd::Zero(std::max(N - 1, 0), std::max(N + 1, 0));
}

}  // namespace exercise
