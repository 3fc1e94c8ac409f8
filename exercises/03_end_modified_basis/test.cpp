#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/interface/multiplier_space.hpp"
#include "common/interface/trace_transfer.hpp"
#include "exercise.hpp"

namespace {
const int element_counts[] = {2, 3, 5, 7, 12};

// Which end elements are constant: both (the paper's M_h^1, the library's end_modified_p1), one
// (a contact line with one end that is no crosspoint), or neither (continuous P1 throughout).
struct Ends {
  bool first, last;
};
const Ends end_cases[] = {{true, true}, {true, false}, {false, true}, {false, false}};

// The free nodal values along Gamma_c for N >= 2: all nodes but 0 (tied to node 1) on a constant
// first element and N (tied to node N - 1) on a constant last one.
std::vector<int> kept_nodes(int N, Ends ends) {
  std::vector<int> nodes;
  for (int j = 0; j <= N; ++j)
    if (!(ends.first && j == 0) && !(ends.last && j == N)) nodes.push_back(j);
  return nodes;
}

std::string name(int N, Ends ends) {
  return "N = " + std::to_string(N) + ", constant first element " + (ends.first ? "yes" : "no") + ", last " +
         (ends.last ? "yes" : "no");
}

// check(N, ends, C, nodes) for every element count and choice of ends, once C has one row per
// free nodal value and one column per node
template <class Check>
void for_every_case(const Check& check) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::end_modified_basis(N, ends.first, ends.last);
      const std::vector<int> nodes = kept_nodes(N, ends);
      const bool shaped = C.rows() == static_cast<int>(nodes.size()) && C.cols() == N + 1;
      EXPECT_TRUE(shaped) << name(N, ends) << ": C is " << C.rows() << " x " << C.cols() << ", expected "
                          << nodes.size() << " x " << N + 1;
      if (shaped) check(N, ends, C, nodes);
    }
}
}  // namespace

// Both ends constant is the paper's M_h^1, which the library builds (for N = 1 too).
TEST(EndModifiedBasis, equals_the_library_basis) {
  for (int N : {1, 2, 3, 5, 12}) {
    const Eigen::MatrixXd C = exercise::end_modified_basis(N, true, true);
    const Eigen::MatrixXd reference = Eigen::MatrixXd(mortar::end_modified_p1(mortar::uniform_trace(1.0, N)).C);
    ASSERT_EQ(C.rows(), reference.rows()) << "N = " << N;
    ASSERT_EQ(C.cols(), reference.cols()) << "N = " << N;
    EXPECT_EQ((C - reference).cwiseAbs().maxCoeff(), 0.0) << "N = " << N << ", C =\n" << C;
  }
}

TEST(EndModifiedBasis, has_one_function_per_free_nodal_value) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::end_modified_basis(N, ends.first, ends.last);
      EXPECT_EQ(C.rows(), N + 1 - ends.first - ends.last)
          << name(N, ends) << ": one function per node, less one per constant end element";
      EXPECT_EQ(C.cols(), N + 1) << name(N, ends) << ": one column per trace node";
    }
}

TEST(EndModifiedBasis, sums_to_one_so_the_projection_keeps_the_integral) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::end_modified_basis(N, ends.first, ends.last);
      ASSERT_EQ(C.cols(), N + 1) << name(N, ends);
      for (int j = 0; j <= N; ++j) EXPECT_DOUBLE_EQ(C.col(j).sum(), 1.0) << name(N, ends) << ": sum_r psi_r at node " << j;
    }
}

TEST(EndModifiedBasis, is_constant_on_the_constant_end_elements) {
  for (int N : element_counts)
    for (Ends ends : end_cases) {
      const Eigen::MatrixXd C = exercise::end_modified_basis(N, ends.first, ends.last);
      ASSERT_EQ(C.cols(), N + 1) << name(N, ends);
      for (int r = 0; r < C.rows(); ++r) {
        if (ends.first) {
          EXPECT_EQ(C(r, 0), C(r, 1)) << name(N, ends) << ": psi_" << r << " on the first element";
        }
        if (ends.last) {
          EXPECT_EQ(C(r, N - 1), C(r, N)) << name(N, ends) << ": psi_" << r << " on the last element";
        }
      }
    }
  // the same check for N = 7 as before: only the first function lives on element 0
  const Eigen::MatrixXd C = exercise::end_modified_basis(7, true, true);
  ASSERT_EQ(C.cols(), 8);
  EXPECT_EQ(C(0, 0), C(0, 1));
  EXPECT_EQ(C.col(0).sum(), C(0, 0));
}

TEST(EndModifiedBasis, is_the_nodal_basis_of_the_free_nodes) {
  // row r is 1 at its own free node and 0 at every other free node
  for_every_case([](int N, Ends ends, const Eigen::MatrixXd& C, const std::vector<int>& nodes) {
    for (int r = 0; r < C.rows(); ++r)
      for (int k = 0; k < C.rows(); ++k)
        EXPECT_EQ(C(r, nodes[k]), r == k ? 1.0 : 0.0) << name(N, ends) << ": psi_" << r << " at node " << nodes[k];
  });
}

TEST(EndModifiedBasis, spans_every_continuous_p1_function_constant_on_the_constant_end_elements) {
  // v continuous P1 with random nodal values, the tied end value equal to its neighbour's:
  // v = sum_r v(free node r) psi_r at every node
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for_every_case([&](int N, Ends ends, const Eigen::MatrixXd& C, const std::vector<int>& nodes) {
    Eigen::VectorXd v(N + 1);
    for (int j = 0; j <= N; ++j) v[j] = value(rng);
    if (ends.first) v[0] = v[1];
    if (ends.last) v[N] = v[N - 1];
    Eigen::VectorXd lambda(C.rows());
    for (int r = 0; r < C.rows(); ++r) lambda[r] = v[nodes[r]];
    EXPECT_LT((C.transpose() * lambda - v).cwiseAbs().maxCoeff(), 1e-15) << name(N, ends);
  });
}

// Worked by hand from the space's conditions (the library has no one-sided basis). N = 3, first
// element constant: v_0 = v_1, the free values v_1, v_2, v_3, dimension N = 3, and the function
// of v_1 is phi_0 + phi_1. Both ends constant: v_0 = v_1 and v_3 = v_2, dimension N - 1 = 2. Only
// the last: the mirror image of the first. Neither: the hats themselves. N = 2 with both: the
// one free value v_1 = v_0 = v_2, psi = 1. N = 1 with one end constant: the element is the whole
// trace, psi = 1 again.
TEST(EndModifiedBasis, matches_cases_worked_by_hand) {
  Eigen::MatrixXd first(3, 4), both(2, 4), last(3, 4);
  first << 1, 1, 0, 0,  //
      0, 0, 1, 0,       //
      0, 0, 0, 1;
  both << 1, 1, 0, 0,  //
      0, 0, 1, 1;
  last << 1, 0, 0, 0,  //
      0, 1, 0, 0,      //
      0, 0, 1, 1;
  const struct {
    int N;
    Ends ends;
    Eigen::MatrixXd expected;
  } cases[] = {{3, {true, false}, first},
               {3, {true, true}, both},
               {3, {false, true}, last},
               {3, {false, false}, Eigen::MatrixXd::Identity(4, 4)},
               {2, {true, true}, Eigen::MatrixXd::Ones(1, 3)},
               {1, {true, false}, Eigen::MatrixXd::Ones(1, 2)},
               {1, {false, true}, Eigen::MatrixXd::Ones(1, 2)}};
  for (const auto& c : cases) {
    const Eigen::MatrixXd C = exercise::end_modified_basis(c.N, c.ends.first, c.ends.last);
    ASSERT_EQ(C.rows(), c.expected.rows()) << name(c.N, c.ends);
    ASSERT_EQ(C.cols(), c.expected.cols()) << name(c.N, c.ends);
    EXPECT_EQ((C - c.expected).cwiseAbs().maxCoeff(), 0.0) << name(c.N, c.ends) << ", C =\n" << C;
  }
}

TEST(EndModifiedBasis, refuses_an_empty_trace) {
  EXPECT_THROW(exercise::end_modified_basis(0, true, true), std::invalid_argument);
  EXPECT_THROW(exercise::end_modified_basis(-2, false, false), std::invalid_argument);
}
