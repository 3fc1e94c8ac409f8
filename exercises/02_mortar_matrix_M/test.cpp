#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/interface/mortar_matrices.hpp"
#include "exercise.hpp"

namespace {
std::string grid(const std::vector<double>& x) {
  std::string s = "{";
  for (double p : x) s += (s.size() > 1 ? ", " : "") + std::to_string(p);
  return s + "}";
}

void expect_matrix(const std::vector<double>& x1, const std::vector<double>& x2, const Eigen::MatrixXd& expected) {
  const Eigen::MatrixXd P = exercise::mixed_mass(x1, x2);
  ASSERT_EQ(P.rows(), expected.rows()) << "x1 = " << grid(x1) << ": one row per node of x1";
  ASSERT_EQ(P.cols(), expected.cols()) << "x2 = " << grid(x2) << ": one column per node of x2";
  EXPECT_LT((P - expected).cwiseAbs().maxCoeff(), 1e-15) << "x1 = " << grid(x1) << ", x2 = " << grid(x2) << ", P =\n"
                                                         << P << "\nexpected\n"
                                                         << expected;
}
}  // namespace

TEST(MortarMatrixM, C_times_P_is_the_library_M) {
  for (auto [n1, n2] : {std::pair{4, 7}, {9, 5}, {6, 6}}) {
    const mortar::InterfaceTrace t1 = mortar::uniform_trace(1.5, n1, 0.3, 3), t2 = mortar::uniform_trace(1.5, n2, 0.3, 4);
    const mortar::MultiplierSpace space = mortar::end_modified_p1(t1);
    const mortar::MortarMatrices m = mortar::mortar_matrices(t1, t2, mortar::merge_traces(t1, t2), space);
    const Eigen::MatrixXd mine = Eigen::MatrixXd(space.C) * exercise::mixed_mass(t1.x, t2.x);
    EXPECT_LT((mine - Eigen::MatrixXd(m.M)).cwiseAbs().maxCoeff(), 1e-14) << n1 << " / " << n2 << " elements";
  }
}

TEST(MortarMatrixM, rows_sum_to_the_integral_of_each_hat) {
  const mortar::InterfaceTrace t1 = mortar::uniform_trace(1.0, 5, 0.2, 1), t2 = mortar::uniform_trace(1.0, 8, 0.2, 2);
  const Eigen::MatrixXd P = exercise::mixed_mass(t1.x, t2.x);
  ASSERT_EQ(P.rows(), 6);
  for (int j = 0; j < t1.num_nodes(); ++j) {
    const double left = j > 0 ? t1.x[j] - t1.x[j - 1] : 0, right = j < 5 ? t1.x[j + 1] - t1.x[j] : 0;
    EXPECT_NEAR(P.row(j).sum(), 0.5 * (left + right), 1e-15) << "int phi^1_" << j;
  }
}

// int phi^1_j phi^2_k = int phi^2_k phi^1_j: swapping the grids transposes P.
TEST(MortarMatrixM, swapping_the_grids_transposes_P) {
  for (auto [n1, n2] : {std::pair{4, 7}, {9, 5}}) {
    const mortar::InterfaceTrace t1 = mortar::uniform_trace(1.5, n1, 0.3, 3), t2 = mortar::uniform_trace(1.5, n2, 0.3, 4);
    const Eigen::MatrixXd P12 = exercise::mixed_mass(t1.x, t2.x), P21 = exercise::mixed_mass(t2.x, t1.x);
    ASSERT_EQ(P21.rows(), P12.cols());
    ASSERT_EQ(P21.cols(), P12.rows());
    EXPECT_LT((P21 - P12.transpose()).cwiseAbs().maxCoeff(), 1e-15) << n1 << " / " << n2 << " elements";
  }
}

// Worked by exact integration of the piecewise-linear products (sympy, rational nodes): one
// side-1 element [0, 1] against side-2 elements [0, 1/2] and [1/2, 1]; e.g.
// P_00 = int_0^{1/2} (1 - x)(1 - 2x) dx = 1/2 - 3/8 + 1/12 = 5/24.
TEST(MortarMatrixM, matches_a_case_worked_by_hand) {
  Eigen::MatrixXd expected(2, 3);
  expected << 5.0 / 24, 1.0 / 4, 1.0 / 24,  //
      1.0 / 24, 1.0 / 4, 5.0 / 24;
  expect_matrix({0, 1}, {0, 0.5, 1}, expected);
}

// Grids that do not share their ends, which the library's merge refuses: P is integrated over
// the part both grids cover. Exact integrals as above (sympy, over [max of the starts, min of
// the ends]); e.g. in the first case P_01 = int_0^{1/2} (1 - x) 2x dx = 1/4 - 1/12 = 1/6.
TEST(MortarMatrixM, integrates_over_the_part_both_grids_cover) {
  Eigen::MatrixXd half(2, 2);  // side 2 covers the first half of side 1's one element
  half << 5.0 / 24, 1.0 / 6,   //
      1.0 / 24, 1.0 / 12;
  expect_matrix({0, 1}, {0, 0.5}, half);
  expect_matrix({0, 0.5}, {0, 1}, half.transpose());  // and the other way round
  Eigen::MatrixXd middle(3, 2);                        // side 2 inside side 1, ends in its elements
  middle << 81.0 / 3200, 9.0 / 3200,                   //
      1157.0 / 5760, 973.0 / 5760,                     //
      343.0 / 14400, 1127.0 / 14400;
  expect_matrix({0, 0.4, 1}, {0.25, 0.75}, middle);
  Eigen::MatrixXd overhang(3, 3);  // side 2 beyond both ends of side 1
  overhang << 27.0 / 400, 277.0 / 2100, 1.0 / 1680,  //
      9.0 / 400, 213.0 / 700, 41.0 / 560,            //
      0, 2.0 / 21, 11.0 / 105;
  expect_matrix({0.2, 0.6, 1}, {0, 0.5, 1.2}, overhang);
  expect_matrix({0, 1}, {2, 3}, Eigen::MatrixXd::Zero(2, 2));  // apart: nothing in common
}
