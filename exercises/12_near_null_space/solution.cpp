#include "exercise.hpp"

#include <map>

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

std::vector<ChangedRow> changed_rows(const Eigen::SparseMatrix<double>& T) {
  // T = I - E, E nonzero only in pivot rows and in columns that are no pivots: E E = 0, so
  // T^{-1} = I + E. V = N + E N changes the pivot rows only, by c_k = E_sk = -T_sk = B_ik / b_i.
  std::map<Eigen::Index, ChangedRow> rows;
  for (Eigen::Index k = 0; k < T.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(T, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0) {
        rows[it.row()].s = it.row();
        rows[it.row()].terms.emplace_back(it.col(), -it.value());
      }
  std::vector<ChangedRow> out;
  for (const auto& [s, row] : rows) out.push_back(row);
  return out;
}

Eigen::MatrixXd modes_in_condensed_unknowns(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N) {
  // v_s = u_s + sum_k (B_ik / b_i) u_k at each pivot, v = u elsewhere: no solve
  Eigen::MatrixXd V = N;
  for (const ChangedRow& row : changed_rows(T))
    for (const auto& [k, c] : row.terms) V.row(row.s) += c * N.row(k);
  return V;
}

Eigen::MatrixXd modes_on_aggregate(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N,
                                   const std::vector<Eigen::Index>& aggregate) {
  // z vanishes outside the aggregate, so u = T z has u_s = z_s + sum_{k in aggregate} T_sk z_k
  // at a pivot. The energy vanishes when u is the motion, u_s = N_s: the pivot's value takes
  // only the mortar unknowns the aggregate holds. With none of them z_s = N_s (N), with all of
  // them z_s = V_s (V), with some of them neither.
  std::vector<Eigen::Index> where(T.rows(), -1);
  for (std::size_t j = 0; j < aggregate.size(); ++j) where[aggregate[j]] = static_cast<Eigen::Index>(j);
  Eigen::MatrixXd Z(static_cast<Eigen::Index>(aggregate.size()), N.cols());
  for (std::size_t j = 0; j < aggregate.size(); ++j) Z.row(static_cast<Eigen::Index>(j)) = N.row(aggregate[j]);
  for (const ChangedRow& row : changed_rows(T)) {
    if (where[row.s] < 0) continue;
    for (const auto& [k, c] : row.terms)
      if (where[k] >= 0) Z.row(where[row.s]) += c * N.row(k);
  }
  return Z;
}

Eigen::VectorXd precondition_condensed(const CondensedOperators& ops, const Eigen::VectorXd& r) {
  // A^{-1} = T^{-1} K^{-1} T^{-T}, so T^{-1} M^{-1} T^{-T} is exact when M is; and as
  // T^{-1} = I + E = 2 I - T, each of T^{-1} and T^{-T} costs one product.
  const Eigen::VectorXd y = 2 * r - ops.T_transpose(r);
  const Eigen::VectorXd z = ops.M_inverse(y);
  return 2 * z - ops.T(z);
}

}  // namespace exercise
