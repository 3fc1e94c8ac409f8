#include "exercise.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace exercise {

Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1, bool linear_first, bool linear_last) {
  const int N = trace1.num_elements();
  // N = 1 with both ends linear: the one element holds a1 and a2, M_h^1 is P1 on it (dimension
  // 2) but its only interior node, the midpoint, is the one folded away; refused, as the
  // library refuses it.
  if (trace1.degree != 2 || N < 2)
    throw std::invalid_argument("p2_multiplier_basis: needs a P2 trace of at least 2 elements, got degree " +
                                std::to_string(trace1.degree) + " with " + std::to_string(N));
  // The free nodal values: every node but the midpoint of a linear end element, whose value is
  // the mean of its element's end values (a quadratic is a line when its middle value lies on
  // the chord).
  std::vector<int> kept;
  for (int j = 0; j <= 2 * N; ++j)
    if (!(linear_first && j == 1) && !(linear_last && j == 2 * N - 1)) kept.push_back(j);
  const int rows = static_cast<int>(kept.size());
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(rows, 2 * N + 1);
  for (int r = 0; r < rows; ++r) C(r, kept[r]) = 1.0;
  // a folded midpoint goes half to the row of either end of its element (for N = 2 with both
  // ends linear, the middle row takes both halves)
  if (linear_first) {
    C(0, 1) += 0.5;
    C(1, 1) += 0.5;
  }
  if (linear_last) {
    C(rows - 2, 2 * N - 1) += 0.5;
    C(rows - 1, 2 * N - 1) += 0.5;
  }
  return C;
}

}  // namespace exercise
