#include "level.hpp"

#include <cmath>

#include "common/contact/bilateral_contact.hpp"
#include "common/fem/errors.hpp"
#include "common/interface/interface_trace.hpp"
#include "common/timing/stopwatch.hpp"
#include "krylov.hpp"

namespace chapter11 {

Scene make_scene(const Options& o) {
  Scene s;
  const mortar::Material m1(o.E1, o.nu1), m2(o.E2, o.nu2);
  const double x0 = o.L / 2, R = o.R;
  s.exact = std::make_unique<const mortar::HertzHalfPlanes>(m1, m2, x0, o.L * std::sqrt(2.0) / 6, R);
  s.gap = [x0, R](double x) { return (x - x0) * (x - x0) / (2 * R); };
  return s;
}

Level make_level(const Options& o, const Scene& scene, int index) {
  const mortar::TwoBodyGeometry g = mortar::two_body_geometry(o, o.n0 << index, 1.0);
  Level level{index, true, g, mortar::make_two_bodies(g, scene.exact->material(0), scene.exact->material(1)), {}, 0, 0, 0, 0,
              {}, scene.gap, {}};
  level.data = mortar::manufactured_scene_all_sides(level.bodies, *scene.exact);
  level.h1 = o.L / g.n1;
  level.h2 = o.L / g.n2;
  level.h = level.bodies.max_edge_length();
  level.count_krylov = level.bodies.num_dofs() <= o.krylov_max_dofs;
  if (o.gap == "interpolated") {
    // the merged grid's breakpoints as a bare P1 trace, g at its nodes
    mortar::InterfaceTrace grid;
    for (const mortar::NitscheSegment& s : mortar::nitsche_segments(level.bodies, {})) grid.x.push_back(s.a);
    grid.x.push_back(o.L);
    grid.nodes.assign(grid.x.size(), -1);
    std::vector<double> value;
    for (double xi : grid.x) value.push_back(scene.gap(xi));
    level.gap = [grid, value](double p) { return grid.evaluate(value, p); };
  }
  // from a / 2 inside the zone to a / 4 outside its right edge, 600 points
  const double a = scene.exact->half_width(), x0 = scene.exact->centre();
  for (int k = 0; k <= 600; ++k) level.sample_x.push_back(x0 + 0.5 * a + k * 0.75 * a / 600);
  return level;
}

mortar::NitscheOptions method_options(const Options& o, const std::string& method) {
  mortar::NitscheOptions n;
  n.linear_solver = o.linear_solver == "sparse" ? mortar::NitscheLinearSolver::sparse : mortar::NitscheLinearSolver::condensed;
  if (method == "nitsche") {
    n.theta = o.theta;
    n.gamma0 = o.gamma0;
    n.body1_weight = body1_weight(o);
    n.harmonic_weight = o.traction == "harmonic";
    return n;
  }
  n.penalty = true;
  n.gamma0 = o.penalty_gamma0;
  n.body1_weight = 1;
  // penalty_fixed: the value gamma0 E1 / h1 takes on the coarsest level, on every level
  if (method == "penalty_fixed") n.fixed_gamma = o.penalty_gamma0 * o.E1 / (o.L / o.n0);
  return n;
}

std::pair<double, double> displacement_errors(const Level& level, const Scene& scene, const Eigen::VectorXd& u) {
  mortar::ErrorNorms norms;
  for (int l = 0; l < 2; ++l)
    norms += mortar::error_norms(level.bodies.body(l).mesh, level.bodies.body(l).material, level.bodies.part(u, l),
                                 scene.exact->exact(l));
  return {norms.relative_energy(), norms.relative_l2()};
}

MethodResult run_without_multipliers(const Level& level, const Scene& scene, const std::string& name,
                                     const mortar::NitscheOptions& options, const Level* coarser,
                                     const MethodResult* coarse_result) {
  MethodResult r;
  r.name = name;
  const mortar::Stopwatch clock;
  Eigen::VectorXd start;
  if (coarser != nullptr && coarse_result != nullptr) {
    // nested iteration: the level below's answer, interpolated body by body (the levels nest)
    start.resize(level.bodies.num_dofs());
    for (int l = 0; l < 2; ++l)
      start.segment(level.bodies.offset(l), level.bodies.body(l).mesh.num_dofs()) = mortar::interpolate_from_rectangle(
          mortar::body_rectangle(coarser->geometry, l), coarser->bodies.part(coarse_result->u, l), level.bodies.body(l).mesh);
  }
  mortar::NitscheOptions run = options;
  run.keep_last_matrix = level.count_krylov;
  const mortar::NitscheSolution s =
      mortar::solve_nitsche_contact(level.bodies, level.data, level.gap, run, start.size() > 0 ? &start : nullptr);
  r.time_s = clock.seconds();
  r.u = s.u;
  r.residual = s.residual;
  r.lu_fallbacks = s.lu_fallbacks;
  r.failure = s.failure;
  if (level.count_krylov) {
    r.krylov_counted = true;
    r.krylov_iterations = krylov_iterations(s.last_matrix, options.penalty || options.theta == 1);
  }
  r.newton_steps = s.newton_steps;
  r.converged = s.converged;
  r.solver = s.solver;
  std::tie(r.err_energy, r.err_l2) = displacement_errors(level, scene, s.u);
  const auto pressure = mortar::nitsche_pressure(s.segments, level.gap, options, s.u);
  const auto exact_p = [&](double x) { return scene.exact->pressure(x); };
  const auto [error, norm] = mortar::pressure_l2_error(pressure, exact_p, scene.exact->pressure_kinks());
  r.err_pressure = error / norm;
  r.half_width_error_m = std::fabs(mortar::contact_half_width(pressure) - scene.exact->half_width());
  r.total_force = mortar::total_force(pressure);
  std::size_t k = 0;
  for (double x : level.sample_x) {
    while (k + 1 < pressure.size() && pressure[k].b < x) ++k;
    r.pressure_samples.push_back(pressure[k].active ? pressure[k].at(x) : 0.0);
  }
  return r;
}

}  // namespace chapter11
