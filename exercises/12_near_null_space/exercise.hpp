// Exercise 12: the near-null space that algebraic multigrid is told, for chapter 9.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace exercise {

// The motions of a 2D elastic body that cost no strain energy, at its nodes: a matrix with one
// row per dof (node k's x and y dofs in rows 2k and 2k + 1) and one column per motion, as many
// columns as there are independent such motions of a body in the plane.
Eigen::MatrixXd rigid_body_modes(const std::vector<std::array<double, 2>>& nodes);

// Below, T is chapter 9's condensation u = T v (g = 0): the identity but in its pivot rows s_i,
// where u_{s_i} = v_{s_i} - sum_k (B_ik / b_i) v_k, the k running over dofs that are no pivots.
// The matrix AMG would see is A = T^T K T.

// The same motions in the unknowns v: returns V with T V = N.
Eigen::MatrixXd modes_in_condensed_unknowns(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N);

// A row s in which V = T^{-1} N can differ from N: for every N, v_s = u_s + sum of c u_k over
// its terms (k, c), k != s, read row by row from a column u of N and its column v of V.
struct ChangedRow {
  Eigen::Index s = 0;
  std::vector<std::pair<Eigen::Index, double>> terms;
};
// Every such row of T^{-1}, from T alone, in any order: a row in which v_s = u_s for every N is
// not one of them.
std::vector<ChangedRow> changed_rows(const Eigen::SparseMatrix<double>& T);

// The motions of N seen by A on one aggregate, a set of unknowns of v (both dofs of each of its
// nodes). A's matrix there is T^T K_agg T, with K_agg assembled from the elements whose nodes
// all lie in the aggregate. Returns Z, one row per unknown of `aggregate` (in its order), one
// column per column of N, such that each column z, extended by zero outside the aggregate,
//   - equals N at the aggregate's unknowns that are no pivots (it is the same motion), and
//   - costs no energy, z^T T^T K_agg T z = 0, for every stiffness K_agg whose kernel holds the
//     motions of N (every pivot of the aggregate lies in one of its elements).
Eigen::MatrixXd modes_on_aggregate(const Eigen::SparseMatrix<double>& T, const Eigen::MatrixXd& N,
                                   const std::vector<Eigen::Index>& aggregate);

// What chapter 9 holds of T, K and the preconditioner M of K: products, no entries.
using Operator = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
struct CondensedOperators {
  Operator T;            // x -> T x
  Operator T_transpose;  // x -> T^T x
  Operator M_inverse;    // r -> M^{-1} r, M a preconditioner of K (GAMG in chapter 9)
};
// A preconditioner of A = T^T K T built from M, applied to r: it returns A^{-1} r exactly when
// M^{-1} = K^{-1}, and costs at most one product with T, one with T^T and one with M^{-1}, as
// chapter 9 applies it at every CG iteration.
Eigen::VectorXd precondition_condensed(const CondensedOperators& ops, const Eigen::VectorXd& r);

}  // namespace exercise
