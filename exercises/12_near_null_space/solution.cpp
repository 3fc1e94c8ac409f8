#include "exercise.hpp"

#include <Eigen/SparseLU>

namespace exercise {

Eigen::MatrixXd rigid_body_modes(const std::vector<std::array<double, 2>>& nodes) {
  // eps(u) = 0 in the plane: u = a + theta (-y, x), two translations and one rotation
  const auto n = static_cast<Eigen::Index>(nodes.size());
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(2 * n, 3);
  for (Eigen::Index k = 0; k < n; ++k) {
    N(2 * k, 0) = 1;
    N(2 * k + 1, 1) = 1;
    N(2 * k, 2) = -nodes[k][1];
    N(2 * k + 1, 2) = nodes[k][0];
  }
  return N;
}

Eigen::MatrixXd modes_in_condensed_unknowns(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(T);
  return lu.solve(N);
}

}  // namespace exercise
