#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd rigid_body_modes(const std::vector<std::array<double, 2>>& nodes) {
  // Your code here: which displacement fields have a zero symmetric gradient? How many are
  // there in the plane? Write each one's value at every node.
  return Eigen::MatrixXd::Zero(2 * static_cast<Eigen::Index>(nodes.size()), 1);
}

Eigen::MatrixXd modes_in_condensed_unknowns(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N) {
  // Your code here: V with T V = N.
  (void)T;
  return N;
}

std::vector<ChangedRow> changed_rows(const Eigen::SparseMatrix<double>& T) {
  // Your code here: which rows of T are not the identity's, and what is T^{-1} in those rows?
  // (Which columns can E = I - T have nonzeros in, and what is E E?)
  (void)T;
  return {};
}

Eigen::MatrixXd modes_on_aggregate(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N,
                                   const std::vector<Eigen::Index>& aggregate) {
  // Your code here: z is zero outside the aggregate. What is (T z)_s at a pivot s of the
  // aggregate, and what must it be for u = T z to cost no energy?
  (void)T;
  return Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(aggregate.size()), N.cols());
}

Eigen::VectorXd precondition_condensed(const CondensedOperators& ops, const Eigen::VectorXd& r) {
  // Your code here: write A^{-1} with K^{-1} and T, then apply T's inverses with one product each.
  return ops.M_inverse(r);
}

}  // namespace exercise
