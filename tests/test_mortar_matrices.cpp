#include <gtest/gtest.h>

#include "common/interface/mortar_matrices.hpp"

using namespace mortar;

namespace {
MortarMatrices build(const InterfaceTrace& t1, const InterfaceTrace& t2) {
  return mortar_matrices(t1, t2, merge_traces(t1, t2), end_modified_p1(t1));
}
// int psi_i: psi = sum_j C_ij phi_j and int phi_j = half the length of the elements at j
Eigen::VectorXd psi_integrals(const InterfaceTrace& t) {
  const MultiplierSpace m = end_modified_p1(t);
  Eigen::VectorXd phi_int = Eigen::VectorXd::Zero(t.num_nodes());
  for (int e = 0; e < t.num_elements(); ++e) {
    phi_int[e] += 0.5 * (t.x[e + 1] - t.x[e]);
    phi_int[e + 1] += 0.5 * (t.x[e + 1] - t.x[e]);
  }
  return m.C * phi_int;
}
}  // namespace

TEST(MortarMatrices, row_sums_of_D_and_M_equal_the_integral_of_psi) {
  const InterfaceTrace t1 = uniform_trace(2.0, 9, 0.4, 3), t2 = uniform_trace(2.0, 14, 0.4, 5);
  const MortarMatrices m = build(t1, t2);
  const Eigen::VectorXd expected = psi_integrals(t1);
  const Eigen::VectorXd D_rows = m.D * Eigen::VectorXd::Ones(t1.num_nodes());
  const Eigen::VectorXd M_rows = m.M * Eigen::VectorXd::Ones(t2.num_nodes());
  ASSERT_EQ(D_rows.size(), expected.size());
  EXPECT_LT((D_rows - expected).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((M_rows - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(MortarMatrices, matching_traces_give_D_equal_to_M) {
  const InterfaceTrace t = uniform_trace(1.0, 8, 0.3, 2);
  const MortarMatrices m = build(t, t);
  EXPECT_LT(Eigen::MatrixXd(m.D - m.M).cwiseAbs().maxCoeff(), 1e-16);
}

TEST(MortarMatrices, traces_1e14_apart_give_the_matching_D_and_M) {
  const InterfaceTrace t1 = uniform_trace(1.0, 12, 0.3, 4);
  InterfaceTrace t2 = t1;
  for (int i = 1; i + 1 < t2.num_nodes(); ++i) t2.x[i] += (i % 3 - 1) * 1e-14;
  const MortarMatrices near = build(t1, t2), exact = build(t1, t1);
  EXPECT_LT(Eigen::MatrixXd(near.D - exact.D).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT(Eigen::MatrixXd(near.M - exact.M).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_TRUE(Eigen::MatrixXd(near.M).allFinite());
}

TEST(MortarMatrices, D_is_the_mass_matrix_folded_at_the_ends) {
  // Uniform h = 1/4: D row of psi_2 = phi_2 is (0, h/6, 2h/3, h/6, 0).
  const InterfaceTrace t = uniform_trace(1.0, 4);
  const MortarMatrices m = build(t, uniform_trace(1.0, 7));
  const double h = 0.25;
  EXPECT_NEAR(m.D.coeff(1, 1), h / 6, 1e-16);
  EXPECT_NEAR(m.D.coeff(1, 2), 2 * h / 3, 1e-16);
  EXPECT_NEAR(m.D.coeff(1, 3), h / 6, 1e-16);
  // psi_1 = phi_0 + phi_1: int (phi_0 + phi_1) phi_0 = h/3 + h/6
  EXPECT_NEAR(m.D.coeff(0, 0), h / 2, 1e-16);
}
