#include "unilateral_level.hpp"

#include <algorithm>
#include <cmath>

#include <limits>
#include <optional>

#include "common/contact/bilateral_contact.hpp"
#include "common/contact/dual_condensation.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/timing/stopwatch.hpp"

namespace chapter05 {

namespace {
// [u_h.n] is P1 on the merged grid; g is not: check its breakpoints and the midpoints between.
void measure_penetration(UnilateralLevel& r) {
  const mortar::InterfaceCurve& j = r.jump;
  r.max_penetration = -std::numeric_limits<double>::infinity();
  r.penetration_round_off = 0;
  for (std::size_t k = 0; k < j.x.size(); ++k)
    for (double t : {0.0, 0.5}) {
      if (t > 0 && k + 1 == j.x.size()) break;
      const double x = t > 0 ? 0.5 * (j.x[k] + j.x[k + 1]) : j.x[k];
      const double value = t > 0 ? 0.5 * (j.value[k] + j.value[k + 1]) : j.value[k];
      r.penetration_round_off = std::max({r.penetration_round_off, 1e-9 * std::fabs(value), 1e-9 * std::fabs(r.gap(x))});
      if (value - r.gap(x) > r.max_penetration) {
        r.max_penetration = value - r.gap(x);
        r.max_penetration_x = x;
      }
    }
}
}  // namespace

UnilateralLevel solve_unilateral_level(const UnilateralSetup& setup,
                                       const mortar::ExactContact& exact) {
  return solve_unilateral_level(mortar::make_two_bodies(setup.geometry, exact.material(0), exact.material(1)),
                                setup, exact);
}

UnilateralLevel solve_unilateral_level(mortar::TwoBodies bodies, const UnilateralSetup& setup,
                                       const mortar::ExactContact& exact) {
  UnilateralLevel r{std::move(bodies), {}, {}, {}, {}, {}, {}, {}, {}};
  std::optional<UnilateralScene> scene;
  // Steps 1-7, timed: everything but the mesh.
  const auto solve = [&] {
    // 1. The scene: loads, Dirichlet data and the initial gap g(x) >= 0 (scenes.cpp).
    {
      const mortar::ProfilePhase phase("scene (loads and gap)");
      scene = make_scene(setup.scene, r.bodies, exact);
    }
    r.gap = scene->gap;
    // 2. K of both bodies, block diagonal: the bodies only meet through B.
    mortar::SparseMatrix K = r.bodies.stiffness();
    // 3. The interface: Gamma_c as chapter 4 builds it, both traces, their merged grid, M_h^1,
    //    D and M (chapter 4's level.cpp takes these steps one by one).
    r.gamma = setup.dual_newton ? mortar::make_dual_interface(r.bodies, setup.nonmortar)
                                : mortar::make_interface(r.bodies, setup.nonmortar);
    // 4. The constraint rows of the chosen matching: chapter 3's pointwise rows at the nodes
    //    xi^1 or chapter 4's rows D, M against M_h^1, attached to the normal dofs as B.
    r.constraints = mortar::constraint_rows(r.bodies, r.gamma, mortar::matching_rows(r.gamma, setup.matching),
                                            scene->data.prescribed_mask(r.bodies.num_dofs()));
    // 5. The tested gap G: g at the nodes xi^1 (pointwise) or int g psi_i (integral), so that
    //    the discrete convex set K_h^P or K_h^I is B u <= G.
    const Eigen::VectorXd G = mortar::tested_gap(r.gamma, r.constraints, scene->gap);

    // 6. Dirichlet elimination: the prescribed dofs leave the system; their values move into f
    //    and into the gap, G - B u_d.
    mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, scene->data.F, scene->data.dirichlet);
    mortar::SaddlePointProblem reduced = mortar::reduce_to_free_dofs(system, r.constraints, G);
    // From here on one stiffness matrix is enough, the one the solver factorizes, as in the
    // physical limit: the factor is the memory peak, and every other copy of K would add to it.
    // (Eigen 3.4's SparseMatrix has no move: swap hands its storage over, or frees it.)
    mortar::SparseMatrix().swap(K);
    mortar::SparseMatrix().swap(system.K);
    // 7. The contact solve: min 1/2 u.Ku - f.u subject to B u <= G, by Uzawa or the active set
    //    (common/contact/contact_solvers.cpp); lambda >= 0 is the pressure's multiplier.
    if (setup.dual_newton) {
      // (chapter 6: D diagonal, the non-mortar normal dofs condensed, Newton in the displacements)
      mortar::CondensedContact condensed = mortar::condense_contact(reduced);
      mortar::SparseMatrix().swap(reduced.K);
      mortar::DualContactOptions options;
      options.backend = setup.solver.backend;
      const mortar::DualContactSolution x = mortar::solve_dual_contact(condensed, options);
      r.solution.u = x.u;
      r.solution.lambda = x.lambda;
      r.solution.iterations = x.iterations;
      r.solution.residual = x.residual;
      r.solution.active_set_changes = x.active_set_changes;
      r.solution.active_history = x.active_history;
    } else {
      mortar::ContactProblem problem{{}, std::move(reduced.f), {}, std::move(reduced.G)};
      problem.K.swap(reduced.K);
      problem.B.swap(reduced.B);
      r.solution = mortar::solve_contact(problem, setup.solver);
    }
    r.u = system.expand(r.solution.u);
  };
  if (setup.measure_limit) {
    r.timing = mortar::time_against_limit(
        solve, [&] { return mortar::two_body_limit_matrix(r.bodies, scene->data); }, setup.repetitions);
    r.time_s = r.timing.time_s;
    r.limit_s = r.timing.limit_s;
  } else {
    const mortar::Stopwatch clock;
    solve();
    r.time_s = clock.seconds();
  }

  // 8. What the solve means on Gamma_c: pressure, jump, contact zone, penetration, total force.
  r.pressure = mortar::contact_pressure(r.gamma, r.constraints, r.solution.lambda);
  r.jump = mortar::normal_jump(r.bodies, r.gamma, r.u);
  r.zone = mortar::contact_zone(r.pressure);
  measure_penetration(r);
  r.total_force = mortar::total_contact_force(r.gamma, r.constraints, r.solution.lambda);
  const bool body1 = r.gamma.nonmortar == 0;
  r.h1 = (body1 ? r.gamma.nonmortar_trace : r.gamma.mortar_trace).max_element_length();
  r.h2 = (body1 ? r.gamma.mortar_trace : r.gamma.nonmortar_trace).max_element_length();
  return r;
}

}  // namespace chapter05
