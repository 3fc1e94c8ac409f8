#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

#include "common/fem/p1_elasticity.hpp"
#include "exercise.hpp"

using exercise::changed_rows;
using exercise::ChangedRow;
using exercise::modes_in_condensed_unknowns;
using exercise::modes_on_aggregate;
using exercise::precondition_condensed;
using exercise::rigid_body_modes;

namespace {
using Nodes = std::vector<std::array<double, 2>>;
using Triangles = std::vector<std::array<int, 3>>;

// A small unstructured body: a 3 x 2 grid of a 3 x 2 rectangle, moved away from the origin,
// its inner nodes jittered, each cell cut into two triangles.
Nodes body_nodes() {
  Nodes nodes;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) {
      const bool inner = i > 0 && i < 3 && j == 1;
      nodes.push_back({5.0 + i + (inner ? 0.23 * i : 0.0), -2.0 + j + (inner ? -0.17 : 0.0)});
    }
  return nodes;
}

Triangles body_triangles() {
  Triangles triangles;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 4 * j + i, b = a + 1, c = a + 4, d = a + 5;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  return triangles;
}

// The P1 stiffness of the given triangles, no boundary condition: every rigid motion of each
// connected piece is in its kernel.
Eigen::MatrixXd stiffness(const Nodes& nodes, const Triangles& triangles) {
  const mortar::Material material(210.0, 0.3);
  const auto n = 2 * static_cast<Eigen::Index>(nodes.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (const std::array<int, 3>& t : triangles) {
    std::array<Eigen::Vector2d, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = {nodes[t[k]][0], nodes[t[k]][1]};
    const mortar::ElementMatrix Ke = mortar::element_stiffness(x, material);
    for (int p = 0; p < 6; ++p)
      for (int q = 0; q < 6; ++q) K(2 * t[p / 2] + p % 2, 2 * t[q / 2] + q % 2) += Ke(p, q);
  }
  return K;
}

Eigen::MatrixXd stiffness(const Nodes& nodes) { return stiffness(nodes, body_triangles()); }

// T = I plus the given off-diagonal entries (row, column, value) in the pivot rows.
Eigen::SparseMatrix<double> condensation(Eigen::Index n, std::vector<Eigen::Triplet<double>> entries) {
  for (Eigen::Index k = 0; k < n; ++k) entries.emplace_back(k, k, 1.0);
  Eigen::SparseMatrix<double> T(n, n);
  T.setFromTriplets(entries.begin(), entries.end());
  return T;
}

// The rigid motions of the nodes, written here again (not the student's): the x- and
// y-translations and the rotation (-y, x), in that order.
Eigen::MatrixXd rigid_motions(const Nodes& nodes) {
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(2 * static_cast<Eigen::Index>(nodes.size()), 3);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    N(2 * k, 0) = N(2 * k + 1, 1) = 1;
    N(2 * k, 2) = -nodes[k][1];
    N(2 * k + 1, 2) = nodes[k][0];
  }
  return N;
}

const char* const motion_names[] = {"x-translation", "y-translation", "rotation (-y, x)"};
}  // namespace

TEST(NearNullSpace, every_mode_costs_no_strain_energy) {
  const auto nodes = body_nodes();
  const Eigen::MatrixXd K = stiffness(nodes), N = rigid_body_modes(nodes);
  ASSERT_EQ(N.rows(), K.rows());
  for (Eigen::Index c = 0; c < N.cols(); ++c) {
    ASSERT_GT(N.col(c).norm(), 0) << "mode " << c << " is zero";
    EXPECT_LT((K * N.col(c)).norm(), 1e-12 * K.norm() * N.col(c).norm()) << "mode " << c << " strains the body";
  }
}

TEST(NearNullSpace, the_modes_span_the_whole_kernel_of_a_free_body) {
  const auto nodes = body_nodes();
  const Eigen::MatrixXd K = stiffness(nodes), N = rigid_body_modes(nodes);
  // the kernel of K, from its eigenvalues: as many directions as rigid motions in the plane
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K);
  const double largest = eigen.eigenvalues().maxCoeff();
  Eigen::Index kernel = 0;
  while (eigen.eigenvalues()[kernel] < 1e-10 * largest) ++kernel;
  EXPECT_EQ(N.cols(), kernel) << "one column per independent rigid motion";
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(N).rank(), N.cols()) << "the columns must be independent";
  // every kernel direction is a combination of the columns of N
  for (Eigen::Index k = 0; k < kernel; ++k) {
    const Eigen::VectorXd z = eigen.eigenvectors().col(k);
    const Eigen::VectorXd fit = N * N.colPivHouseholderQr().solve(z);
    EXPECT_LT((fit - z).norm(), 1e-9) << "kernel direction " << k << " is not a rigid motion of N";
  }
}

TEST(NearNullSpace, condensed_modes_are_the_rigid_motions_seen_through_T) {
  // u = T v: the pivot row 3 reads u_3 = v_3 - 0.5 v_0 + 0.25 v_4 (a weighted gap's row), the
  // others u_k = v_k
  Eigen::SparseMatrix<double> T(6, 6);
  std::vector<Eigen::Triplet<double>> entries = {{3, 0, -0.5}, {3, 4, 0.25}};
  for (int k = 0; k < 6; ++k) entries.push_back({k, k, 1.0});
  T.setFromTriplets(entries.begin(), entries.end());
  Eigen::MatrixXd N(6, 2);
  N << 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1;
  const Eigen::MatrixXd V = modes_in_condensed_unknowns(T, N);
  ASSERT_EQ(V.rows(), 6);
  ASSERT_EQ(V.cols(), 2);
  EXPECT_LT((Eigen::MatrixXd(T) * V - N).norm(), 1e-14);
  // by hand: v_3 = u_3 + 0.5 u_0 - 0.25 u_4, every other row unchanged
  EXPECT_NEAR(V(3, 0), 0.0 + 0.5 * 1 - 0.25 * 1, 1e-14);
  EXPECT_NEAR(V(3, 1), 1.0 + 0.5 * 0 - 0.25 * 0, 1e-14);
  EXPECT_NEAR(V(0, 0), 1.0, 1e-14);
}

// The README's question, worked by hand. Three nodes on the contact line, node 1 at (0.5, 0) on
// body 1, nodes 0 at (0, 0) and 2 at (1, 0) on body 2; the pivot is node 1's normal dof (row 3),
// and its row u_3 = v_3 + 0.6 v_1 + 0.4 v_5 couples the normal (y) dofs only. Its weights sum to
// one: -B_ik / b_i = 0.6, 0.4, i.e. sum_k B_ik = -b_i, the row reproduces constants. Then
// v_3 = u_3 - 0.6 u_1 - 0.4 u_5 (the gap the motion opens), every other v_k = u_k:
//   x-translation:     0 - 0.6 * 0 - 0.4 * 0     = 0
//   y-translation:     1 - 0.6 * 1 - 0.4 * 1     = 0    (both bodies together: no gap)
//   rotation (-y, x):  0.5 - 0.6 * 0 - 0.4 * 1   = 0.1  (the row does not reproduce x)
//   body 1 up alone:   1 - 0.6 * 0 - 0.4 * 0     = 1
TEST(NearNullSpace, a_translation_of_both_bodies_opens_no_gap_at_a_pivot) {
  Eigen::SparseMatrix<double> T(6, 6);
  std::vector<Eigen::Triplet<double>> entries = {{3, 1, 0.6}, {3, 5, 0.4}};
  for (int k = 0; k < 6; ++k) entries.push_back({k, k, 1.0});
  T.setFromTriplets(entries.begin(), entries.end());
  const double x[3] = {0.0, 0.5, 1.0};  // the nodes' abscissae, all at y = 0
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(6, 4);
  for (int k = 0; k < 3; ++k) {
    N(2 * k, 0) = 1;         // x-translation
    N(2 * k + 1, 1) = 1;     // y-translation
    N(2 * k + 1, 2) = x[k];  // rotation (-y, x): its x part -y vanishes on this line
  }
  N(3, 3) = 1;  // node 1 (body 1) moves up, body 2 stays
  const Eigen::MatrixXd V = modes_in_condensed_unknowns(T, N);
  ASSERT_EQ(V.rows(), 6);
  ASSERT_EQ(V.cols(), 4);
  const double pivot[4] = {0.0, 0.0, 0.1, 1.0};
  const char* motion[4] = {"x-translation", "y-translation", "rotation", "body 1 alone"};
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(V(3, c), pivot[c], 1e-14) << motion[c] << ": the pivot row of V";
    for (int r = 0; r < 6; ++r) {
      if (r == 3) continue;
      EXPECT_NEAR(V(r, c), N(r, c), 1e-14) << motion[c] << ": row " << r << " is no pivot";
    }
  }
}

// --- changed_rows: the rows of V = T^{-1} N that can differ from N, read from T alone ---------

namespace {
// The student's rows as the matrix D of V = N + D N (a repeated term summed).
Eigen::MatrixXd as_matrix(const std::vector<ChangedRow>& rows, Eigen::Index n) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  for (const ChangedRow& row : rows)
    for (const auto& [k, c] : row.terms) D(row.s, k) += c;
  return D;
}

// The rows must be those of the known D, in any order; says what a wrong row means.
void expect_rows(const std::vector<ChangedRow>& rows, const Eigen::MatrixXd& D, const Eigen::SparseMatrix<double>& T) {
  const Eigen::Index n = D.rows();
  std::vector<bool> listed(n, false);
  for (const ChangedRow& row : rows) {
    ASSERT_TRUE(row.s >= 0 && row.s < n) << "row " << row.s << " is no row of T";
    for (const auto& term : row.terms)
      ASSERT_TRUE(term.first >= 0 && term.first < n && term.first != row.s)
          << "row " << row.s << ": the term in u_" << term.first << " is no other row of T";
    EXPECT_FALSE(listed[row.s]) << "row " << row.s << " is listed twice: put all its terms in one row";
    listed[row.s] = true;
  }
  const Eigen::MatrixXd mine = as_matrix(rows, n), Td(T);
  for (Eigen::Index r = 0; r < n; ++r) {
    if (D.row(r).norm() > 0 && !listed[r]) {
      ADD_FAILURE() << "row " << r << " is missing: T's row " << r << " is a pivot's, and v_" << r << " = u_" << r
                    << " would make (T V)_" << r << " = u_" << r << " + sum_k T_" << r << "k u_k"
                    << ": V = N fails at a pivot";
    } else if (D.row(r).norm() == 0 && listed[r]) {
      ADD_FAILURE() << "row " << r << " is listed, but T^{-1} is the identity's there: v_" << r << " = u_" << r
                    << " for every N";
    } else {
      for (Eigen::Index k = 0; k < n; ++k) {
        if (std::fabs(mine(r, k) - D(r, k)) <= 1e-14) continue;
        const bool copied = Td(r, k) != 0 && std::fabs(mine(r, k) - Td(r, k)) <= 1e-14;
        ADD_FAILURE() << "row " << r << ", the term in u_" << k << ": expected " << D(r, k) << ", got " << mine(r, k)
                      << (copied ? ": that is T's own entry, u in terms of v; V needs v in terms of u" : "");
      }
    }
  }
}
}  // namespace

// Worked by hand. The README's T (part 2): u_3 = v_3 + 0.6 v_1 + 0.4 v_5, every other u_k = v_k. Row 3
// solved for v_3: v_3 = u_3 - 0.6 v_1 - 0.4 v_5, and v_1 = u_1, v_5 = u_5 (their rows are the
// identity's), so v_3 = u_3 - 0.6 u_1 - 0.4 u_5: one row, terms (1, -0.6) and (5, -0.4). For the
// y-translation, u_1 = u_3 = u_5 = 1: v_3 = 1 - 0.6 - 0.4 = 0, as the weights sum to one.
// The first condensed test's T: u_3 = v_3 - 0.5 v_0 + 0.25 v_4, so v_3 = u_3 + 0.5 u_0 - 0.25 u_4.
TEST(NearNullSpace, only_the_pivot_rows_change_worked_by_hand) {
  {
    SCOPED_TRACE("T with u_3 = v_3 + 0.6 v_1 + 0.4 v_5");
    const Eigen::SparseMatrix<double> T = condensation(6, {{3, 1, 0.6}, {3, 5, 0.4}});
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, 6);
    D(3, 1) = -0.6;
    D(3, 5) = -0.4;
    const std::vector<ChangedRow> rows = changed_rows(T);
    EXPECT_EQ(rows.size(), 1u) << "T has one pivot row";
    expect_rows(rows, D, T);
    if (HasFatalFailure()) return;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    u(1) = u(3) = u(5) = 1;  // both bodies move along the normal
    const Eigen::VectorXd v = u + as_matrix(rows, 6) * u;
    EXPECT_NEAR(v(3), 0.0, 1e-14) << "a translation of both bodies along the normal opens no gap: v_3 = w / b = 0";
  }
  {
    SCOPED_TRACE("T with u_3 = v_3 - 0.5 v_0 + 0.25 v_4");
    const Eigen::SparseMatrix<double> T = condensation(6, {{3, 0, -0.5}, {3, 4, 0.25}});
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, 6);
    D(3, 0) = 0.5;
    D(3, 4) = -0.25;
    expect_rows(changed_rows(T), D, T);
  }
}

// Two pivots, rows 9 and 11 (normal dofs of body 1), sharing the mortar dof 3, and row 11
// taking a tangential dof 4 too (a curved contact line). The rows are checked against
// T^{-1} - I, inverted densely here.
TEST(NearNullSpace, the_changed_rows_are_those_of_T_inverse) {
  const Eigen::SparseMatrix<double> T =
      condensation(14, {{9, 1, 0.75}, {9, 3, 0.25}, {11, 3, 0.3}, {11, 5, 0.7}, {11, 4, -0.1}});
  Eigen::MatrixXd D = Eigen::MatrixXd(T).fullPivLu().inverse() - Eigen::MatrixXd::Identity(14, 14);
  D = D.unaryExpr([](double d) { return std::fabs(d) < 1e-13 ? 0.0 : d; });  // the inverse's rounding
  expect_rows(changed_rows(T), D, T);
}

// --- modes_on_aggregate: the motions A sees on one aggregate -------------------------------------

namespace {
// Two bodies touching along y = 0, away from the origin so that no mode vanishes at the pivot
// by chance. Body 2 (mortar) below: nodes 0 (2, 0), 1 (3, 0), 2 (2, -1), 3 (3, -1); body 1
// (non-mortar) above: nodes 4 (2, 0), 5 (2.5, 0), 6 (3, 0), 7 (2, 1), 8 (2.5, 1), 9 (3, 1).
// One pivot, node 5's normal dof, row 11, whose row reproduces constants as the README's:
// u_11 = v_11 + 0.6 v_1 + 0.4 v_3, with v_1 and v_3 the normal dofs of mortar nodes 0 and 1.
struct TwoBodies {
  Nodes nodes = {{2, 0}, {3, 0}, {2, -1}, {3, -1}, {2, 0}, {2.5, 0}, {3, 0}, {2, 1}, {2.5, 1}, {3, 1}};
  Triangles triangles = {{2, 3, 1}, {2, 1, 0}, {4, 5, 8}, {4, 8, 7}, {5, 6, 9}, {5, 9, 8}};
  Eigen::SparseMatrix<double> T = condensation(20, {{11, 1, 0.6}, {11, 3, 0.4}});
};
constexpr Eigen::Index pivot = 11;

std::vector<Eigen::Index> dofs_of(const std::vector<int>& nodes) {
  std::vector<Eigen::Index> dofs;
  for (int a : nodes) dofs.insert(dofs.end(), {2 * a, 2 * a + 1});
  return dofs;
}

Eigen::VectorXd restricted(const Eigen::VectorXd& x, const std::vector<Eigen::Index>& dofs) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t j = 0; j < dofs.size(); ++j) r(static_cast<Eigen::Index>(j)) = x(dofs[j]);
  return r;
}

// The energy of z (on the aggregate's dofs, zero elsewhere) in A's matrix on the aggregate,
// T^T K_agg T, K_agg assembled from the triangles whose three nodes the aggregate holds.
double energy_on_aggregate(const TwoBodies& b, const std::vector<int>& nodes, const Eigen::VectorXd& z) {
  const auto holds = [&](int a) { return std::find(nodes.begin(), nodes.end(), a) != nodes.end(); };
  Triangles inside;
  for (const std::array<int, 3>& t : b.triangles)
    if (holds(t[0]) && holds(t[1]) && holds(t[2])) inside.push_back(t);
  const std::vector<Eigen::Index> dofs = dofs_of(nodes);
  Eigen::VectorXd full = Eigen::VectorXd::Zero(b.T.rows());
  for (std::size_t j = 0; j < dofs.size(); ++j) full(dofs[j]) = z(static_cast<Eigen::Index>(j));
  const Eigen::VectorXd u = b.T * full;
  return u.dot(stiffness(b.nodes, inside) * u);
}

struct AggregateCase {
  const char* name;
  std::vector<int> nodes;
  std::array<double, 3> at_pivot;  // z_11 for each motion, by hand
  const char* why;
};

// Energy as the test reports it: zero below rounding.
double reported(double energy, double scale) { return std::fabs(energy) < 1e-10 * scale ? 0.0 : energy; }

void check_aggregate(const TwoBodies& b, const AggregateCase& c, const Eigen::MatrixXd& N, const Eigen::MatrixXd& V) {
  const double scale = stiffness(b.nodes, b.triangles).norm();
  const std::vector<Eigen::Index> dofs = dofs_of(c.nodes);
  const Eigen::MatrixXd Z = modes_on_aggregate(b.T, N, dofs);
  ASSERT_EQ(Z.rows(), static_cast<Eigen::Index>(dofs.size())) << "one row per unknown of the aggregate";
  ASSERT_EQ(Z.cols(), 3) << "one column per column of N";
  for (int m = 0; m < 3; ++m) {
    const Eigen::VectorXd n = restricted(N.col(m), dofs), v = restricted(V.col(m), dofs);
    for (std::size_t j = 0; j < dofs.size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      if (dofs[j] != pivot)
        EXPECT_NEAR(Z(i, m), n(i), 1e-14)
            << motion_names[m] << ": unknown " << dofs[j] << " is no pivot, z is the motion itself there";
      else
        EXPECT_NEAR(Z(i, m), c.at_pivot[m], 1e-14)
            << motion_names[m] << " at the pivot (unknown 11): " << c.why << ". Restricted to this aggregate, N costs "
            << reported(energy_on_aggregate(b, c.nodes, n), scale) << " and V costs "
            << reported(energy_on_aggregate(b, c.nodes, v), scale);
    }
    const double e = energy_on_aggregate(b, c.nodes, Z.col(m));
    EXPECT_LE(std::fabs(e), 1e-10 * scale * Z.col(m).squaredNorm())
        << motion_names[m] << " costs " << e << " in A's matrix on the aggregate: T z is not rigid at the pivot";
  }
}
}  // namespace

// The README's question, worked by hand: one patch of body 1 (nodes 4-9, the pivot among them)
// with none, both or one of the pivot's mortar nodes. z is zero outside the aggregate and N at
// its other unknowns; u = T z is rigid on body 1's triangles only if u_11 = z_11 + 0.6 z_1 +
// 0.4 z_3 = N_11, with z_1, z_3 zero unless the aggregate holds them. For the x-translation,
// the y-translation and the rotation (-y, x), whose y part is x: N_1 = (0, 1, 2),
// N_3 = (0, 1, 3), N_11 = (0, 1, 2.5), and
//   none, nodes 4-9:          z_11 = N_11                        = (0, 1,   2.5)  N's values
//   both, nodes 0, 1, 4-9:    z_11 = N_11 - 0.6 N_1 - 0.4 N_3    = (0, 0,   0.1)  V's values
//   node 1 only, nodes 1, 4-9: z_11 = N_11 - 0.4 N_3             = (0, 0.6, 1.3)  neither
// N serves the first aggregate, V the second, neither the third. Each column's energy in A's
// matrix on the aggregate is checked too, and a failure says what N and V would cost there.
TEST(NearNullSpace, an_aggregates_modes_depend_on_the_mortar_nodes_it_holds) {
  const TwoBodies b;
  const Eigen::MatrixXd N = rigid_motions(b.nodes);
  const Eigen::MatrixXd V = Eigen::MatrixXd(b.T).fullPivLu().solve(N);
  const AggregateCase cases[] = {
      {"body 1's patch, none of the pivot's mortar nodes", {4, 5, 6, 7, 8, 9}, {0.0, 1.0, 2.5},
       "z_1 = z_3 = 0 outside the aggregate, so u_11 = z_11: the pivot keeps N's value"},
      {"body 1's patch and both mortar nodes", {0, 1, 4, 5, 6, 7, 8, 9}, {0.0, 0.0, 0.1},
       "u_11 = z_11 + 0.6 N_1 + 0.4 N_3 must be N_11: the pivot takes V's value, the gap the motion opens"},
      {"body 1's patch and mortar node 1 only", {1, 4, 5, 6, 7, 8, 9}, {0.0, 0.6, 1.3},
       "u_11 = z_11 + 0.4 N_3: only the mortar node held counts, and the value is neither N's nor V's"},
  };
  for (const AggregateCase& c : cases) {
    SCOPED_TRACE(c.name);
    check_aggregate(b, c, N, V);
  }
}

// --- precondition_condensed: a preconditioner of A from one of K --------------------------------

namespace {
// Applies the student's preconditioner with counted products: chapter 9 applies it at every CG
// iteration, so inverting T must not cost a solve.
Eigen::VectorXd precondition_counted(const Eigen::SparseMatrix<double>& T, const exercise::Operator& M_inverse,
                                     const Eigen::VectorXd& r) {
  int with_T = 0, with_T_transpose = 0, with_M = 0;
  const exercise::CondensedOperators ops{
      [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { ++with_T; return T * x; },
      [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { ++with_T_transpose; return T.transpose() * x; },
      [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { ++with_M; return M_inverse(x); }};
  const Eigen::VectorXd z = precondition_condensed(ops, r);
  EXPECT_LE(with_T, 1) << "products with T: one gives T^{-1} x (what is (I - T)^2?)";
  EXPECT_LE(with_T_transpose, 1) << "products with T^T: one gives T^{-T} x";
  EXPECT_EQ(with_M, 1) << "applications of M^{-1}: one per CG iteration";
  return z;
}

constexpr const char* exact_hint =
    "; M^{-1} alone inverts K, not A = T^T K T, and T M^{-1} T^T would invert it only if T^{-1} = T^T";
}  // namespace

// Worked by hand. T = (1 0; 0.5 1), i.e. u_1 = v_1 + 0.5 v_0, K = diag(2, 4), r = (1, 1).
// A = T^T K T = (1 0.5; 0 1)(2 0; 2 4) = (3 2; 2 4), and A^{-1} r = (4 -2; -2 3) r / 8 = (0.25, 0.125).
// The wrong answers: M^{-1} r = K^{-1} r = (0.5, 0.25); T K^{-1} T^T r = T K^{-1} (1.5, 1) =
// T (0.75, 0.25) = (0.75, 0.625).
TEST(NearNullSpace, the_preconditioner_is_exact_for_A_worked_by_hand) {
  const Eigen::SparseMatrix<double> T = condensation(2, {{1, 0, 0.5}});
  const exercise::Operator K_inverse = [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return Eigen::Vector2d(x(0) / 2, x(1) / 4);
  };
  const Eigen::VectorXd z = precondition_counted(T, K_inverse, Eigen::Vector2d(1.0, 1.0));
  ASSERT_EQ(z.size(), 2);
  EXPECT_LT((z - Eigen::Vector2d(0.25, 0.125)).norm(), 1e-15)
      << "got " << z.transpose() << ", A^{-1} r = (0.25, 0.125)" << exact_hint;
}

// The two bodies of the aggregates, each node on a spring of stiffness 1 so that K is SPD:
// with M^{-1} = K^{-1} (a dense solve) the result must be A^{-1} r, A formed and solved here.
TEST(NearNullSpace, the_preconditioner_is_exact_for_A_when_M_is_exact_for_K) {
  const TwoBodies b;
  const Eigen::MatrixXd K = stiffness(b.nodes, b.triangles) + Eigen::MatrixXd::Identity(20, 20);
  const Eigen::MatrixXd Td(b.T), A = Td.transpose() * K * Td;
  const Eigen::LDLT<Eigen::MatrixXd> K_ldlt(K);
  const exercise::Operator K_inverse = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return K_ldlt.solve(x); };
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(20, 1.0, -2.0).array().sin();
  const Eigen::VectorXd z = precondition_counted(b.T, K_inverse, r), exact = A.ldlt().solve(r);
  ASSERT_EQ(z.size(), 20);
  EXPECT_LT((z - exact).norm(), 1e-12 * exact.norm()) << "A z - r = " << (A * z - r).norm() << exact_hint;
}

// With an inexact M (Jacobi, diag(K)) the preconditioned A must have the eigenvalues of M^{-1} K:
// the preconditioner of A is as good as M is for K.
TEST(NearNullSpace, the_preconditioned_A_has_the_eigenvalues_of_M_inverse_K) {
  const TwoBodies b;
  const Eigen::MatrixXd K = stiffness(b.nodes, b.triangles) + Eigen::MatrixXd::Identity(20, 20);
  const Eigen::MatrixXd Td(b.T), A = Td.transpose() * K * Td;
  const Eigen::VectorXd d = K.diagonal();
  const exercise::Operator jacobi = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return x.cwiseQuotient(d); };
  Eigen::MatrixXd PA(20, 20);
  for (Eigen::Index j = 0; j < 20; ++j) PA.col(j) = precondition_counted(b.T, jacobi, A.col(j));
  // M^{-1} K is similar to the symmetric D^{-1/2} K D^{-1/2}: real eigenvalues
  const Eigen::VectorXd s = d.cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd expected =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s.asDiagonal() * K * s.asDiagonal()).eigenvalues();
  const Eigen::VectorXcd mine = PA.eigenvalues();
  std::vector<double> real(20);
  for (Eigen::Index j = 0; j < 20; ++j) {
    EXPECT_LT(std::fabs(mine(j).imag()), 1e-9) << "eigenvalue " << mine(j) << " of the preconditioned A is not real";
    real[j] = mine(j).real();
  }
  std::sort(real.begin(), real.end());
  for (Eigen::Index j = 0; j < 20; ++j)
    EXPECT_NEAR(real[j], expected(j), 1e-9 * expected.maxCoeff())
        << "eigenvalue " << j << ": the preconditioned A must be similar to M^{-1} K";
}
