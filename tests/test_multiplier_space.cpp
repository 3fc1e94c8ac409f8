#include <gtest/gtest.h>

#include "common/interface/multiplier_space.hpp"

using namespace mortar;

TEST(MultiplierSpace, has_dimension_n_minus_1_and_sums_to_one) {
  for (int n : {2, 3, 7}) {
    const MultiplierSpace m = end_modified_p1(uniform_trace(1.0, n));
    EXPECT_EQ(m.dim(), n - 1);
    const Eigen::MatrixXd C = Eigen::MatrixXd(m.C);
    // psi = C phi and sum_j phi_j = 1: the column sums of C must all be one
    for (int j = 0; j <= n; ++j) EXPECT_DOUBLE_EQ(C.col(j).sum(), 1.0) << "n = " << n << ", node " << j;
    EXPECT_GE(C.minCoeff(), 0.0);
  }
}

TEST(MultiplierSpace, is_constant_on_the_end_elements) {
  const MultiplierSpace m = end_modified_p1(uniform_trace(1.0, 5));
  const Eigen::MatrixXd C = Eigen::MatrixXd(m.C);
  // on element 0 only psi_1 = phi_0 + phi_1 lives, with equal coefficients: a constant
  EXPECT_EQ(C(0, 0), 1.0);
  EXPECT_EQ(C(0, 1), 1.0);
  EXPECT_EQ(C.col(0).sum(), C(0, 0));
  EXPECT_EQ(C(3, 4), 1.0);
  EXPECT_EQ(C(3, 5), 1.0);
}

TEST(MultiplierSpace, single_element_gets_one_constant) {
  const MultiplierSpace m = end_modified_p1(uniform_trace(1.0, 1));
  EXPECT_EQ(m.dim(), 1);
  EXPECT_EQ(m.C.coeff(0, 0), 1.0);
  EXPECT_EQ(m.C.coeff(0, 1), 1.0);
}
