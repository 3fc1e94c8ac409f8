#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
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

// Which end elements are linear: both (the paper's M_h^1, the library's end_modified_p2), one
// (a contact line with one end that is no crosspoint), or neither (continuous P2 throughout).
struct Ends {
  bool first, last;
};
const Ends end_cases[] = {{true, true}, {true, false}, {false, true}, {false, false}};

// The free nodes along Gamma_c: all but the midpoints of the linear end elements.
std::vector<int> kept_nodes(int N, Ends ends) {
  std::vector<int> nodes;
  for (int j = 0; j <= 2 * N; ++j)
    if (!(ends.first && j == 1) && !(ends.last && j == 2 * N - 1)) nodes.push_back(j);
  return nodes;
}

std::string name(int N, Ends ends) {
  return "N = " + std::to_string(N) + ", linear first element " + (ends.first ? "yes" : "no") + ", last " +
         (ends.last ? "yes" : "no");
}
}  // namespace

TEST(P2MultiplierBasis, has_one_function_per_free_nodal_value) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::p2_multiplier_basis(p2_trace(N), ends.first, ends.last);
      EXPECT_EQ(C.rows(), 2 * N + 1 - ends.first - ends.last)
          << name(N, ends) << ": one function per node, less one per linear end element";
      EXPECT_EQ(C.cols(), 2 * N + 1) << name(N, ends) << ": one column per P2 trace node";
    }
}

TEST(P2MultiplierBasis, sums_to_one_so_the_projection_keeps_the_integral) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const mortar::InterfaceTrace t = p2_trace(N);
      const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t, ends.first, ends.last);
      ASSERT_EQ(C.cols(), 2 * N + 1);
      for (int j = 0; j <= 2 * N; ++j)
        EXPECT_DOUBLE_EQ(C.col(j).sum(), 1.0) << name(N, ends) << ": sum_r C(r, j) at node " << j;
      for (double x : {0.0, 0.03, 0.31, 0.5, 0.77, 0.98, 1.0}) {
        double sum = 0;
        for (int r = 0; r < C.rows(); ++r) sum += psi(C, r, t, x);
        EXPECT_NEAR(sum, 1.0, 1e-14) << name(N, ends) << ": sum_r psi_r at x = " << x;
      }
    }
}

TEST(P2MultiplierBasis, is_linear_on_the_linear_end_elements) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const mortar::InterfaceTrace t = p2_trace(N);
      const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t, ends.first, ends.last);
      ASSERT_EQ(C.cols(), 2 * N + 1);
      std::vector<int> linear;
      if (ends.first) linear.push_back(0);
      if (ends.last) linear.push_back(N - 1);
      for (int r = 0; r < C.rows(); ++r)
        for (int e : linear) {
          const double a = t.x[e], b = t.x[e + 1];
          const double left = psi(C, r, t, a), right = psi(C, r, t, b);
          for (double s : {0.17, 0.5, 0.83}) {
            const double x = a + s * (b - a);
            EXPECT_NEAR(psi(C, r, t, x), (1 - s) * left + s * right, 1e-14)
                << name(N, ends) << ": psi_" << r << " on end element " << e << " at s = " << s;
          }
        }
    }
}

TEST(P2MultiplierBasis, is_the_nodal_basis_of_the_free_nodes) {
  // psi_r is 1 at its own node, along Gamma_c, and 0 at every other free node
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const mortar::InterfaceTrace t = p2_trace(N);
      const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t, ends.first, ends.last);
      const std::vector<int> nodes = kept_nodes(N, ends);
      ASSERT_EQ(C.rows(), static_cast<int>(nodes.size())) << name(N, ends);
      for (int r = 0; r < C.rows(); ++r)
        for (int k = 0; k < C.rows(); ++k)
          EXPECT_NEAR(psi(C, r, t, t.node_x(nodes[k])), r == k ? 1.0 : 0.0, 1e-14)
              << name(N, ends) << ": psi_" << r << " at node " << nodes[k];
    }
}

TEST(P2MultiplierBasis, spans_every_continuous_p2_function_linear_on_the_linear_end_elements) {
  // v continuous P2 with random values at the free nodes, the midpoints of the linear end
  // elements the mean of their element's end values: v = sum_r v(free node r) psi_r at every node
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::p2_multiplier_basis(p2_trace(N), ends.first, ends.last);
      const std::vector<int> nodes = kept_nodes(N, ends);
      ASSERT_EQ(C.rows(), static_cast<int>(nodes.size())) << name(N, ends);
      ASSERT_EQ(C.cols(), 2 * N + 1);
      Eigen::VectorXd v(2 * N + 1);
      for (int j = 0; j <= 2 * N; ++j) v[j] = value(rng);
      if (ends.first) v[1] = 0.5 * (v[0] + v[2]);
      if (ends.last) v[2 * N - 1] = 0.5 * (v[2 * N - 2] + v[2 * N]);
      Eigen::VectorXd lambda(C.rows());
      for (int r = 0; r < C.rows(); ++r) lambda[r] = v[nodes[r]];
      EXPECT_LT((C.transpose() * lambda - v).cwiseAbs().maxCoeff(), 1e-15) << name(N, ends);
    }
}

// Both ends linear is the paper's M_h^1, which the library builds (chapter 7).
TEST(P2MultiplierBasis, equals_the_library_basis_with_both_ends_linear) {
  for (int N : element_counts) {
    const mortar::InterfaceTrace t = p2_trace(N);
    const Eigen::MatrixXd C = exercise::p2_multiplier_basis(t, true, true);
    const Eigen::MatrixXd reference = Eigen::MatrixXd(mortar::end_modified_p2(t).C);
    ASSERT_EQ(C.rows(), reference.rows());
    ASSERT_EQ(C.cols(), reference.cols());
    EXPECT_EQ((C - reference).cwiseAbs().maxCoeff(), 0.0) << "N = " << N << ", C =\n" << C;
  }
}

TEST(P2MultiplierBasis, refuses_one_element_and_p1_traces) {
  EXPECT_THROW(exercise::p2_multiplier_basis(mortar::uniform_trace(1.0, 1, 0, 1, 2), true, true), std::invalid_argument);
  EXPECT_THROW(exercise::p2_multiplier_basis(mortar::uniform_trace(1.0, 4, 0, 1, 1), true, true), std::invalid_argument);
}
