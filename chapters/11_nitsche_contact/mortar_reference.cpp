#include "mortar_reference.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/contact/contact_solvers.hpp"
#include "common/contact/dual_condensation.hpp"
#include "common/contact/pressure_norms.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/timing/stopwatch.hpp"
#include "krylov.hpp"

namespace chapter11 {

namespace {
// The nodal pressure between its nodes (P1), 0 beyond the trace.
double sample(const mortar::InterfaceCurve& c, double x) {
  const auto it = std::upper_bound(c.x.begin(), c.x.end(), x);
  if (it == c.x.begin() || it == c.x.end()) return 0.0;
  const std::size_t e = it - c.x.begin() - 1;
  const double t = (x - c.x[e]) / (c.x[e + 1] - c.x[e]);
  return (1 - t) * c.value[e] + t * c.value[e + 1];
}
}  // namespace

MethodResult run_mortar(const Level& level, const Scene& scene, int nonmortar, bool dual) {
  MethodResult r;
  r.name = dual ? "dual" : "mortar";
  const mortar::Stopwatch clock;
  const mortar::TwoBodies& bodies = level.bodies;
  const mortar::SparseMatrix K = bodies.stiffness();
  const mortar::ContactInterface gamma = dual ? mortar::make_dual_interface(bodies, nonmortar - 1)
                                              : mortar::make_interface(bodies, nonmortar - 1);
  const mortar::Constraints c =
      mortar::constraint_rows(bodies, gamma, mortar::matching_rows(gamma, mortar::Matching::integral),
                              level.data.prescribed_mask(bodies.num_dofs()));
  const Eigen::VectorXd G = mortar::tested_gap(gamma, c, level.gap);
  const mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, level.data.F, level.data.dirichlet);
  mortar::SaddlePointProblem reduced = mortar::reduce_to_free_dofs(system, c, G);
  Eigen::VectorXd u_free, lambda;
  std::optional<mortar::CondensedContact> condensed;
  if (dual) {
    condensed = mortar::condense_contact(reduced);
    const mortar::DualContactSolution x = mortar::solve_dual_contact(*condensed, {});
    u_free = x.u;
    lambda = x.lambda;
    r.newton_steps = x.iterations;
  } else {
    mortar::ContactProblem problem{reduced.K, reduced.f, reduced.B, reduced.G};
    const mortar::ContactSolution x = mortar::solve_contact(problem, {});
    u_free = x.u;
    lambda = x.lambda;
    r.newton_steps = x.iterations;
  }
  r.time_s = clock.seconds();
  r.solver = mortar::backend_name(mortar::fastest_spd_backend());
  r.u = system.expand(u_free);
  // the matrix its sparse solves see: K on the free dofs (standard basis), T^T K T (dual)
  if (level.count_krylov) {
    r.krylov_counted = true;
    r.krylov_iterations = krylov_iterations(dual ? condensed->A : reduced.K, true);
  }
  std::tie(r.err_energy, r.err_l2) = displacement_errors(level, scene, r.u);
  const mortar::InterfaceCurve pressure = mortar::contact_pressure(gamma, c, lambda);
  const auto exact_p = [&](double x) { return scene.exact->pressure(x); };
  const mortar::PressureErrors pe = mortar::pressure_errors(gamma, pressure, exact_p, scene.exact->pressure_kinks());
  r.err_pressure = pe.l2 / pe.norm_l2;
  r.half_width_error_m = std::fabs(mortar::contact_zone(pressure).half_width() - scene.exact->half_width());
  r.total_force = mortar::total_contact_force(gamma, c, lambda);
  for (double x : level.sample_x) r.pressure_samples.push_back(sample(pressure, x));
  return r;
}

}  // namespace chapter11
