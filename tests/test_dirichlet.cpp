#include <gtest/gtest.h>

#include "common/fem/dirichlet.hpp"
#include "common/linalg/spd_solver.hpp"

using namespace mortar;

TEST(Dirichlet, elimination_reproduces_a_linear_field_exactly) {
  // Linear data on the whole boundary, no load: the P1 solution is the linear field itself.
  RectangleSpec s;
  s.nx = 12; s.ny = 9; s.jitter = 0.3;
  const Mesh mesh = rectangle_mesh(s);
  const Material mat(1, 0.3);
  auto g = [](const Eigen::Vector2d& p) { return Eigen::Vector2d(0.1 + 0.2 * p.x() - 0.3 * p.y(), 0.4 * p.x() + 0.05 * p.y()); };
  DirichletData data;
  prescribe_on_sides(data, mesh, {Side::bottom, Side::right, Side::top, Side::left}, g);
  const ReducedSystem r = eliminate_dirichlet(assemble_stiffness(mesh, mat), Eigen::VectorXd::Zero(mesh.num_dofs()), data);
  EXPECT_EQ(r.K.rows(), 2 * 11 * 8);
  SpdSolver solver;
  solver.factorize(r.K);
  const Eigen::VectorXd u = r.expand(solver.solve(r.rhs));
  for (int a = 0; a < mesh.num_nodes(); ++a)
    EXPECT_LT((u.segment<2>(2 * a) - g(mesh.nodes[a])).norm(), 1e-13) << "node " << a;
}

TEST(Dirichlet, reduced_matrix_is_the_free_block) {
  RectangleSpec s;
  s.nx = 3; s.ny = 2;
  const Mesh mesh = rectangle_mesh(s);
  const SparseMatrix K = assemble_stiffness(mesh, Material(1, 0.3));
  DirichletData data;
  prescribe_on_sides(data, mesh, {Side::left}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, 2); });
  const ReducedSystem r = eliminate_dirichlet(K, Eigen::VectorXd::Zero(K.rows()), data);
  const Eigen::MatrixXd Kd = Eigen::MatrixXd(K);
  for (int i = 0; i < r.K.rows(); ++i)
    for (int j = 0; j < r.K.cols(); ++j)
      EXPECT_DOUBLE_EQ(r.K.coeff(i, j), Kd(r.free_dofs[i], r.free_dofs[j]));
  EXPECT_EQ(r.full_to_free[0], -1);  // node 0 is on the left side
}

TEST(Dirichlet, rejects_out_of_range_dofs) {
  SparseMatrix K(4, 4);
  K.setIdentity();
  DirichletData data{{7}, {0.0}};
  EXPECT_THROW(eliminate_dirichlet(K, Eigen::VectorXd::Zero(4), data), std::invalid_argument);
}

// New loads and values on the same prescribed dofs: the rhs of a fresh elimination, K_ff kept;
// a different set of prescribed dofs is refused.
TEST(Dirichlet, update_loads_equals_a_fresh_elimination) {
  RectangleSpec s;
  s.nx = 5; s.ny = 4;
  const Mesh mesh = rectangle_mesh(s);
  const SparseMatrix K = assemble_stiffness(mesh, Material(1, 0.3));
  DirichletData first, second;
  prescribe_on_sides(first, mesh, {Side::bottom}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 0); });
  prescribe_on_sides(second, mesh, {Side::bottom}, [](const Eigen::Vector2d& p) { return Eigen::Vector2d(0.1 * p.x(), -0.2); });
  const Eigen::VectorXd F1 = Eigen::VectorXd::Zero(mesh.num_dofs()), F2 = Eigen::VectorXd::LinSpaced(mesh.num_dofs(), -1, 1);
  ReducedSystem updated = eliminate_dirichlet(K, F1, first);
  update_loads(updated, K, F2, second);
  const ReducedSystem fresh = eliminate_dirichlet(K, F2, second);
  EXPECT_LT((updated.rhs - fresh.rhs).norm(), 1e-14 * fresh.rhs.norm());
  EXPECT_EQ((updated.prescribed - fresh.prescribed).norm(), 0.0);
  DirichletData other;
  prescribe_on_sides(other, mesh, {Side::top}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 0); });
  EXPECT_THROW(update_loads(updated, K, F2, other), std::invalid_argument);
}
