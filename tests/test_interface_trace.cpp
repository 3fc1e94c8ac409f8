#include <gtest/gtest.h>

#include "common/interface/interface_trace.hpp"

using namespace mortar;

TEST(InterfaceTrace, trace_of_a_jittered_mesh_is_sorted_and_spans_gamma_c) {
  RectangleSpec s;
  s.x1 = 2; s.nx = 13; s.ny = 4; s.jitter = 0.4;
  const Mesh mesh = rectangle_mesh(s);
  const InterfaceTrace t = trace_on_side(mesh, Side::bottom);
  ASSERT_EQ(t.num_nodes(), 14);
  EXPECT_EQ(t.x.front(), 0.0);
  EXPECT_EQ(t.x.back(), 2.0);
  for (int i = 0; i < t.num_nodes(); ++i) EXPECT_EQ(mesh.nodes[t.nodes[i]].x(), t.x[i]);
}

TEST(InterfaceTrace, locates_points_and_evaluates_p1_functions) {
  const InterfaceTrace t = uniform_trace(1.0, 4);
  EXPECT_EQ(t.element_containing(0.0), 0);
  EXPECT_EQ(t.element_containing(0.3), 1);
  EXPECT_EQ(t.element_containing(1.0), 3);
  const std::vector<double> w = {0, 1, 0, 2, 2};
  EXPECT_DOUBLE_EQ(t.evaluate(w, 0.125), 0.5);
  EXPECT_DOUBLE_EQ(t.evaluate(w, 0.625), 1.0);
  EXPECT_DOUBLE_EQ(t.evaluate(w, 1.0), 2.0);
}

TEST(InterfaceTrace, rejects_bad_grids) {
  EXPECT_THROW(uniform_trace(1.0, 0), std::invalid_argument);
  EXPECT_THROW(uniform_trace(-1.0, 3), std::invalid_argument);
  EXPECT_THROW(uniform_trace(1.0, 3, 0.9), std::invalid_argument);
}

TEST(InterfaceTrace, mass_matrix_integrates_products_of_hats_exactly) {
  const InterfaceTrace t = uniform_trace(2.0, 7, 0.3, 5);
  const Eigen::SparseMatrix<double> M = t.mass_matrix();
  // 1^T M 1 = int 1 = length; x^T M 1 = int x; x^T M x = int x^2 (P1 interpolates 1 and x)
  Eigen::VectorXd one = Eigen::VectorXd::Ones(t.num_nodes()), x(t.num_nodes());
  for (int j = 0; j < t.num_nodes(); ++j) x[j] = t.x[j];
  EXPECT_NEAR(one.dot(M * one), 2.0, 1e-14);
  EXPECT_NEAR(x.dot(M * one), 2.0, 1e-14);
  EXPECT_NEAR(x.dot(M * x), 8.0 / 3, 1e-13);
  EXPECT_LT((Eigen::MatrixXd(M) - Eigen::MatrixXd(M).transpose()).norm(), 1e-16);
}
