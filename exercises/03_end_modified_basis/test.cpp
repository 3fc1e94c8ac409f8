#include <gtest/gtest.h>

#include "common/interface/multiplier_space.hpp"
#include "common/interface/trace_transfer.hpp"
#include "exercise.hpp"

TEST(EndModifiedBasis, equals_the_library_basis) {
  for (int N : {2, 3, 5, 12}) {
    const Eigen::MatrixXd C = exercise::end_modified_basis(N);
    const Eigen::MatrixXd reference = Eigen::MatrixXd(mortar::end_modified_p1(mortar::uniform_trace(1.0, N)).C);
    ASSERT_EQ(C.rows(), reference.rows());
    EXPECT_EQ((C - reference).cwiseAbs().maxCoeff(), 0.0) << "N = " << N;
  }
}

TEST(EndModifiedBasis, sums_to_one_so_the_projection_keeps_the_integral) {
  const int N = 7;
  const Eigen::MatrixXd C = exercise::end_modified_basis(N);
  for (int j = 0; j <= N; ++j) EXPECT_DOUBLE_EQ(C.col(j).sum(), 1.0) << "sum_i psi_i at node " << j;
  // constant on the end elements: only psi_1 lives on element 0, with equal coefficients
  EXPECT_EQ(C(0, 0), C(0, 1));
  EXPECT_EQ(C.col(0).sum(), C(0, 0));
}
