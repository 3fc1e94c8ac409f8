#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "common/fem/p1_elasticity.hpp"
#include "exercise.hpp"

using exercise::rigid_body_modes;
using exercise::modes_in_condensed_unknowns;

namespace {
// A small unstructured body: a 3 x 2 grid of a 3 x 2 rectangle, moved away from the origin,
// its inner nodes jittered, each cell cut into two triangles.
std::vector<std::array<double, 2>> body_nodes() {
  std::vector<std::array<double, 2>> nodes;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) {
      const bool inner = i > 0 && i < 3 && j == 1;
      nodes.push_back({5.0 + i + (inner ? 0.23 * i : 0.0), -2.0 + j + (inner ? -0.17 : 0.0)});
    }
  return nodes;
}

// Its stiffness, no boundary condition: every rigid motion is in its kernel.
Eigen::MatrixXd stiffness(const std::vector<std::array<double, 2>>& nodes) {
  const mortar::Material material(210.0, 0.3);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * static_cast<Eigen::Index>(nodes.size()), 2 * nodes.size());
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 4 * j + i, b = a + 1, c = a + 4, d = a + 5;
      for (const std::array<int, 3>& t : {std::array<int, 3>{a, b, d}, std::array<int, 3>{a, d, c}}) {
        std::array<Eigen::Vector2d, 3> x;
        for (int k = 0; k < 3; ++k) x[k] = {nodes[t[k]][0], nodes[t[k]][1]};
        const mortar::ElementMatrix Ke = mortar::element_stiffness(x, material);
        for (int p = 0; p < 6; ++p)
          for (int q = 0; q < 6; ++q) K(2 * t[p / 2] + p % 2, 2 * t[q / 2] + q % 2) += Ke(p, q);
      }
    }
  return K;
}
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
