#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "common/interface/multiplier_space.hpp"
#include "exercise.hpp"

namespace {
const int element_counts[] = {2, 3, 5, 12};

// A P2 trace of N elements on [0, 1], end points jittered by 0.3 (C must not care).
mortar::InterfaceTrace p2_trace(int N) { return mortar::uniform_trace(1.0, N, 0.3, 7, 2); }

// psi_r at x, from row r of C as nodal values on the trace
double psi(const Eigen::MatrixXd& C, int r, const mortar::InterfaceTrace& t, double x) {
  const Eigen::VectorXd row = C.row(r).transpose();
  return t.evaluate(std::vector<double>(row.data(), row.data() + row.size()), x);
}

// The kept nodes along Gamma_c: all but the end-element midpoints 1 and 2N - 1.
std::vector<int> kept_nodes(int N) {
  std::vector<int> nodes;
  for (int j = 0; j <= 2 * N; ++j)
    if (j != 1 && j != 2 * N - 1) nodes.push_back(j);
  return nodes;
}
}  // namespace

TEST(P2MultiplierBasis, has_one_function_per_interior_node) {
  for (int N : element_counts) {
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(p2_trace(N));
    EXPECT_EQ(C.rows(), 2 * N - 1) << "N = " << N << ": dim M_h^1 = 2N - 1, the interior nodes";
    EXPECT_EQ(C.cols(), 2 * N + 1) << "N = " << N << ": one column per P2 trace node";
  }
}

TEST(P2MultiplierBasis, sums_to_one_so_the_projection_keeps_the_integral) {
  for (int N : element_counts) {
    const mortar::InterfaceTrace t = p2_trace(N);
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t);
    ASSERT_EQ(C.cols(), 2 * N + 1);
    for (int j = 0; j <= 2 * N; ++j)
      EXPECT_DOUBLE_EQ(C.col(j).sum(), 1.0) << "N = " << N << ": sum_r C(r, j) at node " << j;
    for (double x : {0.0, 0.03, 0.31, 0.5, 0.77, 0.98, 1.0}) {
      double sum = 0;
      for (int r = 0; r < C.rows(); ++r) sum += psi(C, r, t, x);
      EXPECT_NEAR(sum, 1.0, 1e-14) << "N = " << N << ": sum_r psi_r at x = " << x;
    }
  }
}

TEST(P2MultiplierBasis, is_linear_on_the_two_end_elements) {
  for (int N : element_counts) {
    const mortar::InterfaceTrace t = p2_trace(N);
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t);
    ASSERT_EQ(C.cols(), 2 * N + 1);
    for (int r = 0; r < C.rows(); ++r)
      for (int e : {0, N - 1}) {
        const double a = t.x[e], b = t.x[e + 1];
        const double left = psi(C, r, t, a), right = psi(C, r, t, b);
        for (double s : {0.17, 0.5, 0.83}) {
          const double x = a + s * (b - a);
          EXPECT_NEAR(psi(C, r, t, x), (1 - s) * left + s * right, 1e-14)
              << "N = " << N << ": psi_" << r << " on end element " << e << " at s = " << s;
        }
      }
  }
}

TEST(P2MultiplierBasis, is_the_nodal_basis_of_the_kept_nodes) {
  // psi_r is 1 at its own node, along Gamma_c, and 0 at every other kept node
  for (int N : element_counts) {
    const mortar::InterfaceTrace t = p2_trace(N);
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t);
    ASSERT_EQ(C.rows(), 2 * N - 1);
    const std::vector<int> nodes = kept_nodes(N);
    for (int r = 0; r < C.rows(); ++r)
      for (int k = 0; k < C.rows(); ++k)
        EXPECT_NEAR(psi(C, r, t, t.node_x(nodes[k])), r == k ? 1.0 : 0.0, 1e-14)
            << "N = " << N << ": psi_" << r << " at node " << nodes[k];
  }
}

TEST(P2MultiplierBasis, spans_every_continuous_p2_function_linear_on_the_end_elements) {
  // v continuous P2 with random values at the kept nodes, the end-element midpoints the mean
  // of their element's end values: v = sum_r v(kept node r) psi_r at every node
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int N : element_counts) {
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(p2_trace(N));
    ASSERT_EQ(C.rows(), 2 * N - 1);
    ASSERT_EQ(C.cols(), 2 * N + 1);
    Eigen::VectorXd v(2 * N + 1);
    for (int j = 0; j <= 2 * N; ++j) v[j] = value(rng);
    v[1] = 0.5 * (v[0] + v[2]);
    v[2 * N - 1] = 0.5 * (v[2 * N - 2] + v[2 * N]);
    const std::vector<int> nodes = kept_nodes(N);
    Eigen::VectorXd lambda(2 * N - 1);
    for (int r = 0; r < C.rows(); ++r) lambda[r] = v[nodes[r]];
    EXPECT_LT((C.transpose() * lambda - v).cwiseAbs().maxCoeff(), 1e-15) << "N = " << N;
  }
}

TEST(P2MultiplierBasis, equals_the_library_basis) {
  for (int N : element_counts) {
    const mortar::InterfaceTrace t = p2_trace(N);
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t);
    const Eigen::MatrixXd reference = Eigen::MatrixXd(mortar::end_modified_p2(t).C);
    ASSERT_EQ(C.rows(), reference.rows());
    ASSERT_EQ(C.cols(), reference.cols());
    EXPECT_EQ((C - reference).cwiseAbs().maxCoeff(), 0.0) << "N = " << N << ", C =\n" << C;
  }
}

TEST(P2MultiplierBasis, refuses_one_element_and_p1_traces) {
  EXPECT_THROW(exercise::p2_multiplier_basis(mortar::uniform_trace(1.0, 1, 0, 1, 2)), std::invalid_argument);
  EXPECT_THROW(exercise::p2_multiplier_basis(mortar::uniform_trace(1.0, 4, 0, 1, 1)), std::invalid_argument);
}
