#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd p2_multiplier_basis(const mortar::InterfaceTrace& trace1) {
  const int N = trace1.num_elements();
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * N - 1, 2 * N + 1);
  // Your code here: refuse a trace that is not P2 or has fewer than 2 elements
  // (std::invalid_argument); one row per kept node (all but 1 and 2N - 1), in order along
  // Gamma_c, with a 1 at that node; then fold each end-element midpoint, half into the row of
  // either end of its element.
  return C;
}

}  // namespace exercise
