#include <gtest/gtest.h>

#include "common/interface/mortar_matrices.hpp"
#include "exercise.hpp"

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
  for (int j = 0; j < t1.num_nodes(); ++j) {
    const double left = j > 0 ? t1.x[j] - t1.x[j - 1] : 0, right = j < 5 ? t1.x[j + 1] - t1.x[j] : 0;
    EXPECT_NEAR(P.row(j).sum(), 0.5 * (left + right), 1e-15) << "int phi^1_" << j;
  }
}
