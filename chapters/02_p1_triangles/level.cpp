#include "level.hpp"

#include <algorithm>

#include "common/fem/dirichlet.hpp"
#include "common/linalg/physical_limit.hpp"
#include "common/timing/stopwatch.hpp"

namespace chapter02 {

using mortar::Side;

namespace {
// Dirichlet on the left and bottom sides (u = exact u there), traction on the other two.
mortar::ReducedSystem assemble_system(const mortar::Mesh& mesh, const mortar::Material& material,
                                      const ManufacturedSolution& exact) {
  const mortar::SparseMatrix K = mortar::assemble_stiffness(mesh, material);
  // sigma(u) is smooth: a degree-4 rule makes the load error far below the O(h^2) L2 error.
  Eigen::VectorXd F = mortar::body_force_vector(
      mesh, [&](const Eigen::Vector2d& p) { return exact.body_force(p); }, 4);
  mortar::add_traction(F, mesh, Side::right,
                       [&](const Eigen::Vector2d& p) { return exact.traction(p, {1, 0}); }, 3);
  mortar::add_traction(F, mesh, Side::top,
                       [&](const Eigen::Vector2d& p) { return exact.traction(p, {0, 1}); }, 3);
  mortar::DirichletData dirichlet;
  mortar::prescribe_on_sides(dirichlet, mesh, {Side::left, Side::bottom},
                             [&](const Eigen::Vector2d& p) { return exact.u(p); });
  return mortar::eliminate_dirichlet(K, F, dirichlet);
}
}  // namespace

LevelResult solve_level(const LevelSetup& setup, const mortar::Material& material,
                        const ManufacturedSolution& exact) {
  LevelResult r;
  mortar::RectangleSpec spec;
  spec.nx = spec.ny = setup.n;
  spec.jitter = setup.jitter;
  r.mesh = mortar::rectangle_mesh(spec);

  // The level's solve, and the floor for this level: K alone, assembled and factorized once,
  // same matrix, same run, both timed the same way (interleaved, the minimum of each).
  const auto solve = [&] {
    mortar::ReducedSystem system;
    {
      const mortar::ProfilePhase phase("assembly and elimination");
      system = assemble_system(r.mesh, material, exact);
    }
    mortar::SpdSolver solver(setup.backend);
    solver.factorize(system.K);
    r.u = system.expand(solver.solve(system.rhs));
  };
  r.timing = mortar::time_against_limit(solve, [&] {
    mortar::DirichletData dirichlet;
    mortar::prescribe_on_sides(dirichlet, r.mesh, {Side::left, Side::bottom},
                               [](const Eigen::Vector2d&) { return Eigen::Vector2d::Zero(); });
    const mortar::SparseMatrix K = mortar::assemble_stiffness(r.mesh, material);
    return mortar::eliminate_dirichlet(K, Eigen::VectorXd::Zero(K.rows()), dirichlet).K;
  });
  r.time_s = r.timing.time_s;
  r.limit_s = r.timing.limit_s;
  r.dofs = r.mesh.num_dofs();
  r.norms = mortar::error_norms(r.mesh, material, r.u, exact.exact());
  return r;
}

}  // namespace chapter02
