#include "exercise.hpp"

#include <stdexcept>
#include <string>

namespace exercise {

Eigen::MatrixXd end_modified_basis(int N, bool constant_first, bool constant_last) {
  if (N < 1) throw std::invalid_argument("end_modified_basis: needs N >= 1 elements, got " + std::to_string(N));
  // One element with a constant end: both of its nodes carry the same value, so the space is
  // the constants, psi = phi_0 + phi_1 = 1 (whether one end or both ask it).
  if (N == 1 && (constant_first || constant_last)) return Eigen::MatrixXd::Ones(1, 2);
  // A function constant on the first element has v_0 = v_1: node 0's value is not free, and
  // its hat goes with node 1's. Likewise node N with node N - 1 at the other end.
  const int first = constant_first ? 1 : 0, last = constant_last ? N - 1 : N;  // the free nodes
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(last - first + 1, N + 1);
  for (int j = first; j <= last; ++j) C(j - first, j) = 1.0;
  if (constant_first) C(0, 0) = 1.0;
  if (constant_last) C(last - first, N) = 1.0;
  return C;
}

}  // namespace exercise
