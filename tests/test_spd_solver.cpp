#include <gtest/gtest.h>

#include "common/dirichlet.hpp"
#include "common/spd_solver.hpp"

using namespace mortar;

namespace {
ReducedSystem clamped_block(int n) {
  RectangleSpec s;
  s.nx = n; s.ny = n; s.jitter = 0.2;
  const Mesh mesh = rectangle_mesh(s);
  DirichletData data;
  prescribe_on_sides(data, mesh, {Side::bottom}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 0); });
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  add_traction(F, mesh, Side::top, [](const Eigen::Vector2d& p) { return Eigen::Vector2d(0.1, -1 - p.x()); }, 2);
  return eliminate_dirichlet(assemble_stiffness(mesh, Material(1, 0.3)), F, data);
}
}  // namespace

TEST(SpdSolver, cholmod_and_simplicial_ldlt_agree) {
  if (!cholmod_available()) GTEST_SKIP() << "this build has no CHOLMOD; the fallback is tested below";
  const ReducedSystem r = clamped_block(40);
  SpdSolver fast(SpdBackend::cholmod), readable(SpdBackend::simplicial_ldlt);
  fast.factorize(r.K);
  readable.factorize(r.K);
  const Eigen::VectorXd a = fast.solve(r.rhs), b = readable.solve(r.rhs);
  EXPECT_LT((a - b).norm(), 1e-10 * a.norm());
}

TEST(SpdSolver, every_backend_solves_to_small_residual_and_reuses_its_factorization) {
  const ReducedSystem r = clamped_block(30);
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    solver.factorize(r.K);
    for (int k = 0; k < 3; ++k) {
      const Eigen::VectorXd rhs = r.rhs * (k + 1) + Eigen::VectorXd::Constant(r.rhs.size(), 0.01 * k);
      const Eigen::VectorXd x = solver.solve(rhs);
      EXPECT_LT((r.K * x - rhs).norm(), 1e-10 * rhs.norm()) << backend_name(b) << ", rhs " << k;
    }
  }
}

TEST(SpdSolver, a_floating_body_is_reported_not_solved) {
  // No Dirichlet data: K has three rigid-body modes and is only semidefinite.
  RectangleSpec s;
  s.nx = 6; s.ny = 6;
  const Mesh mesh = rectangle_mesh(s);
  const SparseMatrix K = assemble_stiffness(mesh, Material(1, 0.3));
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    EXPECT_THROW(solver.factorize(K), std::runtime_error) << backend_name(b);
  }
}

TEST(SpdSolver, solve_before_factorize_is_an_error) {
  SpdSolver solver(SpdBackend::simplicial_ldlt);
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(3)), std::logic_error);
}
