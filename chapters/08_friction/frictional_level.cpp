#include "frictional_level.hpp"

#include <algorithm>
#include <optional>

#include "common/contact/bilateral_contact.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/timing/stopwatch.hpp"

namespace chapter08 {

int FrictionalLevel::newton_steps_max() const {
  int m = 0;
  for (const StepResult& s : steps) m = std::max(m, s.newton_steps);
  return m;
}
int FrictionalLevel::newton_steps_total() const {
  int m = 0;
  for (const StepResult& s : steps) m += s.newton_steps;
  return m;
}
int FrictionalLevel::lu_steps_total() const {
  int m = 0;
  for (const StepResult& s : steps) m += s.solution.lu_steps;
  return m;
}

namespace {
// The first linearization point of a glued start: every node closed (lambda_n + c_n w_n > 0)
// and stuck (z = 0 < s).
std::vector<mortar::NodalUnknowns> glued_start(int nodes) {
  std::vector<mortar::NodalUnknowns> x(static_cast<std::size_t>(nodes));
  for (auto& n : x) n.lambda_n = 1;
  return x;
}
}  // namespace

FrictionalLevel solve_frictional_level(const LevelSetup& setup, const Scene& scene, const mortar::Material& body1,
                                       const mortar::Material& body2) {
  FrictionalLevel r{mortar::make_two_bodies(setup.geometry, body1, body2), {}, {}, {}, {}, 0, 0, {}, 0, 0};
  std::optional<mortar::SceneData> first;
  const auto solve = [&] {
    r.steps.clear();
    // 1. K of both bodies, once: the load path changes loads and data, not K.
    const mortar::SparseMatrix K = r.bodies.stiffness();
    // 2. Gamma_c with chapter 6's dual basis: D diagonal, so each node's conditions are its own.
    r.gamma = mortar::make_dual_interface(r.bodies, setup.nonmortar);
    // 3. Two rows per node: the weighted gap int psi_i [u.n] on the normal dofs, and the
    //    weighted slip int psi_i [u_t] = int psi_i (u^1_x - u^2_x) on the tangential ones.
    first = scene.step_data(r.bodies, 0, setup.normal_force);
    const std::vector<bool> mask = first->prescribed_mask(r.bodies.num_dofs());
    const mortar::MatchingRows rows = mortar::integral_matching_rows(r.gamma);
    r.normal = mortar::constraint_rows(r.bodies, r.gamma, rows, mask);
    r.tangential = mortar::tangential_constraint_rows(r.bodies, r.gamma, rows, mask);
    // 4. The tested gap G_i = int g psi_i, and Tresca's threshold at each row's node.
    const Eigen::VectorXd G = mortar::tested_gap(r.gamma, r.normal, scene.gap);
    const int m = static_cast<int>(G.size());
    Eigen::VectorXd threshold(m);
    for (int i = 0; i < m; ++i) threshold[i] = scene.threshold(r.gamma.nonmortar_trace.node_x(r.normal.row_node[i]));

    // 5. The load path: each step one frictional contact problem, its slip counted from the
    //    last step's (Coulomb is a law for increments), its Newton method started there.
    mortar::FrictionOptions options;
    options.law = setup.law;
    options.friction = setup.friction;
    options.threshold = threshold;
    // one set of factorizations for the whole load path: the pattern of the Newton matrix is
    // fixed by the condensed problem, so CHOLMOD's and UMFPACK's analyses are made once
    options.factorizations = std::make_shared<mortar::FrictionFactorizations>();
    if (scene.start_glued) options.start = glued_start(m);
    if (setup.start_at) {
      // a slip start needs |z| >= s: lambda_t beyond every threshold, in the slip's direction
      const double beyond = 2 * std::max(setup.friction, threshold.size() > 0 ? threshold.maxCoeff() : 0.0) + 1;
      options.start.assign(static_cast<std::size_t>(m), mortar::NodalUnknowns{});
      for (int i = 0; i < m; ++i) {
        const auto [status, sign] = setup.start_at(r.gamma.nonmortar_trace.node_x(r.normal.row_node[i]));
        mortar::NodalUnknowns& x = options.start[i];
        if (status == mortar::NodeStatus::open) x.w_n = -1;
        else x.lambda_n = 1;
        if (status == mortar::NodeStatus::slip) x.lambda_t = sign * beyond;
      }
    }
    // 6. Dirichlet elimination, both sets of rows on the free dofs, stacked, condensed: the
    //    pivots (both dofs of each non-mortar node) become w_n and w_t. Done once: the load path
    //    changes the loads and the prescribed values, not K_ff, T or A = T^T K T.
    mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, first->F, first->dirichlet);
    const mortar::SaddlePointProblem pn = mortar::reduce_to_free_dofs(system, r.normal, G);
    const mortar::SaddlePointProblem pt = mortar::reduce_to_free_dofs(system, r.tangential, Eigen::VectorXd::Zero(m));
    mortar::CondensedContact condensed = mortar::condense_contact(mortar::stack_frictional_rows(pn, pt));
    double normal_force = setup.normal_force;
    for (int step = 0; step < scene.steps; ++step) {
      const mortar::Stopwatch step_clock;
      if (step > 0) {
        // the step's loads: f and the gaps G - B u_d of both row sets, then r = T^T (f - K g)
        const mortar::SceneData data = scene.step_data(r.bodies, step, normal_force);
        mortar::update_loads(system, K, data.F, data.dirichlet);
        Eigen::VectorXd G_step(2 * m);
        G_step << G - r.normal.B * system.prescribed, -(r.tangential.B * system.prescribed);
        mortar::update_condensed_loads(condensed, system.K, system.rhs, G_step);
      }
      // 7. The semismooth Newton method (friction_newton.hpp), or Coulomb by fixed point.
      StepResult s;
      if (setup.fixed_point && setup.law == mortar::FrictionLaw::coulomb) {
        const mortar::FixedPointSolution x = mortar::solve_coulomb_by_fixed_point(condensed, options);
        s.solution = x.last;
        s.newton_steps = x.total_steps;
        s.outer_iterations = x.outer;
      } else {
        try {
          s.solution = mortar::solve_frictional_contact(condensed, options);
        } catch (const std::runtime_error& e) {
          const double E_nm = r.bodies.body(setup.nonmortar).material.E(), E_m = r.bodies.body(1 - setup.nonmortar).material.E();
          if (E_nm <= 10 * E_m) throw;
          throw std::runtime_error(std::string(e.what()) + "; the non-mortar body is " + std::to_string(E_nm / E_m) +
                                   " times stiffer than the other: make the softer body non-mortar (--nonmortar)");
        }
        s.newton_steps = s.solution.steps;
      }
      s.u = system.expand(s.solution.u);
      options.previous_slip = s.solution.w_t;
      options.start = s.solution.nodes;
      options.fixed_point_start = setup.friction * s.solution.lambda_n.cwiseMax(0.0);  // the last step's F p
      for (auto& n : options.start) n.dw_t = 0;
      // 8. What the step says on Gamma_c.
      s.pressure = mortar::contact_pressure(r.gamma, r.normal, s.solution.lambda_n);
      s.shear = mortar::contact_pressure(r.gamma, r.normal, s.solution.lambda_t);  // the same reading
      s.normal_force = mortar::total_contact_force(r.gamma, r.normal, s.solution.lambda_n);
      s.shear_force = mortar::total_contact_force(r.gamma, r.normal, s.solution.lambda_t);
      s.status.assign(s.pressure.x.size(), mortar::NodeStatus::open);
      for (int i = 0; i < m; ++i) s.status[r.normal.row_node[i]] = s.solution.status[i];
      if (step == 0 && !(setup.normal_force > 0)) normal_force = s.normal_force;
      s.time_s = step_clock.seconds();
      r.steps.push_back(std::move(s));
    }
  };
  if (setup.measure_limit) {
    r.timing = mortar::time_against_limit(solve, [&] { return mortar::two_body_limit_matrix(r.bodies, scene.limit_data(r.bodies)); },
                                          setup.repetitions);
    r.time_s = r.timing.time_s;
    r.limit_s = r.timing.limit_s;
  } else {
    const mortar::Stopwatch clock;
    solve();
    r.time_s = clock.seconds();
  }
  const bool body1_nonmortar = r.gamma.nonmortar == 0;
  r.h1 = (body1_nonmortar ? r.gamma.nonmortar_trace : r.gamma.mortar_trace).max_element_length();
  r.h2 = (body1_nonmortar ? r.gamma.mortar_trace : r.gamma.nonmortar_trace).max_element_length();
  return r;
}

std::function<std::pair<mortar::NodeStatus, double>(double x)> nested_start(const FrictionalLevel& coarser) {
  const StepResult& first = coarser.steps.front();
  const std::vector<double> xs = first.pressure.x;
  std::vector<double> sign(xs.size());
  for (std::size_t k = 0; k < xs.size(); ++k) sign[k] = first.shear.value[k] >= 0 ? 1.0 : -1.0;
  const std::vector<mortar::NodeStatus> status = first.status;
  return [xs, sign, status](double x) {
    std::size_t k = static_cast<std::size_t>(std::lower_bound(xs.begin(), xs.end(), x) - xs.begin());
    if (k == xs.size() || (k > 0 && x - xs[k - 1] < xs[k] - x)) --k;
    return std::make_pair(status[k], sign[k]);
  };
}

mortar::ContactZone stick_zone(const StepResult& step) {
  mortar::InterfaceCurve sticking = step.pressure;
  for (std::size_t k = 0; k < sticking.value.size(); ++k)
    sticking.value[k] = step.status[k] == mortar::NodeStatus::stick ? 1.0 : 0.0;
  return mortar::contact_zone(sticking);
}

}  // namespace chapter08
