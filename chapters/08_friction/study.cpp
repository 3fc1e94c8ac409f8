#include "study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <utility>

#include "common/fem/errors.hpp"
#include "common/linalg/memory_estimate.hpp"

namespace chapter08 {

namespace {
// More than this many dofs on the finest level is refused (the memory check below refuses
// earlier on a smaller machine).
constexpr double max_dofs = 4'000'000;
// Peak resident set per dof at the finest level: K, A = T^T K T, the Newton matrix and its
// factor (Cholesky, or UMFPACK's LU, about twice the Cholesky factor).
constexpr double bytes_per_dof = 3000;

}  // namespace

double e_star(const Options& o) { return 1.0 / ((1 - o.nu1 * o.nu1) / o.E1 + (1 - o.nu2 * o.nu2) / o.E2); }

mortar::FrictionLaw law_of(const Options& o) {
  return o.law == "tresca" ? mortar::FrictionLaw::tresca : mortar::FrictionLaw::coulomb;
}

namespace {
// cattaneo-exact: one material unless told (its field needs Dundurs' beta = 0, which it checks),
// the box of the defaults, six levels from n0 = 8 (h1 = 1/8 to 1/256) for local rates; the
// normal load is the field's own, not a displacement of the top
void check_cattaneo_exact(mortar::OptionParser& parser, Options& o) {
  if (!parser.given("E2")) o.E2 = o.E1;
  if (!parser.given("nu2")) o.nu2 = o.nu1;
  if (!parser.given("levels")) o.levels = 6;
  if (parser.given("delta"))
    parser.fail("delta", "the cattaneo-exact scene is loaded by its exact field (half-width L sqrt(2)/6), not by delta");
  const auto dundurs = [](double E, double nu) { return (1 - 2 * nu) * 2 * (1 + nu) / E; };  // (1 - 2 nu) / mu
  const double d1 = dundurs(o.E1, o.nu1), d2 = dundurs(o.E2, o.nu2);
  if (std::fabs(d1 - d2) > 1e-12 * std::max(std::fabs(d1), std::fabs(d2)))
    parser.fail(parser.given("nu2") ? "nu2" : "E2",
                "the cattaneo-exact scene needs Dundurs' beta = 0, (1 - 2 nu1)/mu1 = (1 - 2 nu2)/mu2 (one material, "
                "say): otherwise the shear moves the pressure and Cattaneo-Mindlin's field is no solution");
}
}  // namespace

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  using mortar::Range;
  parser.add_choice("scene", o.scene, {"manufactured", "cattaneo", "cattaneo-exact"},
                    "manufactured: exact Tresca/Coulomb solution with a stick and a slip zone; cattaneo: normal load, then "
                    "shear in steps, against Cattaneo-Mindlin; cattaneo-exact: the same path with the half-planes' "
                    "Cattaneo-Mindlin field prescribed on every outer side, its exact solution");
  parser.add_choice("law", o.law, {"coulomb", "tresca"},
                    "friction law: threshold F lambda_n (coulomb) or the given F p (tresca; manufactured scene only)");
  parser.add_choice("solver", o.solver, {"newton", "fixed-point"},
                    "semismooth Newton on all conditions, or Coulomb as a sequence of Tresca problems");
  parser.add_choice("start", o.start, {"nested", "scene"},
                    "the first Newton step of each level: from the coarser level's stick, slip and open nodes, or the "
                    "scene's own start (glued: every node closed and stuck)");
  parser.add_double("friction", o.friction, "friction coefficient F", Range::closed(0, 1e6));
  parser.add_int("load-steps", o.load_steps, "shear steps after the normal one (cattaneo)", Range::closed(1, 1000));
  parser.add_double("q-ratio", o.q_ratio, "Q / (F P) at the last step (cattaneo; 1 and above: gross sliding)",
                    Range::closed(0, 10));
  parser.add_double("R", o.R, "radius of the gap (x - L/2)^2 / (2R) [m] (cattaneo)", Range::closed(1e-6, 1e12));
  parser.add_double("delta", o.delta, "downward displacement of the top of body 1 [m] (cattaneo; 0.02 unless given)",
                    Range::open(0, 1e6));
  parser.add_int("n0", o.n0, "body-1 elements along Gamma_c on the coarsest level (cattaneo: 16 unless given)",
                 Range::closed(4, 1 << 14));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (manufactured: 7, cattaneo: 5 unless given)",
                 Range::closed(3, 10));
  mortar::add_two_body_options(parser, o);
  parser.add_flag("no-compare", o.no_compare,
                  "skip the solver comparison (manufactured: Newton against the fixed point over F and h) or the load "
                  "paths (cattaneo: Q in one step, P and Q together)");
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (n0 = 8, levels = 3; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  // The softer body is the non-mortar side unless the user chose (bilateral_study.hpp): on the
  // stiffer one the Newton method cycles (E1 = 1e6 E2 with body 1 non-mortar: 50 steps without
  // settling, at 474 dofs).
  mortar::check_stiffness_ratio(parser, o);
  mortar::choose_softer_nonmortar(parser, o);
  // Coulomb's discrete problem loses uniqueness as F grows (Hil02). On the manufactured scene
  // the Newton method, restart included, does not converge from F = 5 on (F = 5, 6, 8, 10 on
  // the --quick levels; on the scene's earlier version every set of statuses of the coarsest
  // level, solved in turn, gave 3 solutions at F = 6 and 41 at F = 10). F = 4 converges like h
  // at every level.
  if (o.scene == "manufactured" && o.friction > 4)
    parser.fail("friction", "beyond F = 4 the Newton method does not converge on the manufactured scene, whose "
                            "discrete Coulomb problem loses uniqueness as F grows: use --scene cattaneo for a large F");
  if (o.scene == "cattaneo") {
    // Cattaneo-Mindlin is for one material (beta = 0) on bodies large against the zone
    if (!parser.given("E2")) o.E2 = o.E1;
    if (!parser.given("nu2")) o.nu2 = o.nu1;
    if (!parser.given("H1")) o.H1 = o.L;
    if (!parser.given("H2")) o.H2 = o.L;
    if (!parser.given("n0")) o.n0 = 16;
    if (!parser.given("delta")) o.delta = 0.02;
    if (!parser.given("levels")) o.levels = 5;
    if (o.delta >= o.H1) parser.fail("delta", "delta must be small against H1 (linear elasticity)");
  }
  if (o.scene == "cattaneo-exact") check_cattaneo_exact(parser, o);
  if (o.scene == "cattaneo" || o.scene == "cattaneo-exact") {
    if (o.law == "tresca") parser.fail("law", "the cattaneo scenes are Coulomb's (their threshold is F lambda_n)");
    if (!(o.friction > 0)) parser.fail("friction", "the cattaneo scenes need F > 0 (Q is a fraction of F P)");
    if (o.q_ratio >= 1)
      parser.fail("q-ratio", "Q >= F P is gross sliding: no stick zone is left, and friction cannot hold body 1 "
                             "(its only support in x); choose --q-ratio below 1");
    // Contact only where the rigid overlap delta - (x - L/2)^2 / (2R) is positive: a zone below
    // one element of the coarsest level is one node, which alone holds body 1 in x, and slips
    // once the shear tilts its pressure (no solution: gross sliding)
    const double overlap = std::sqrt(2 * o.R * o.delta), h = o.L / (o.quick && !parser.given("n0") ? 8 : o.n0);
    if (overlap < h) {
      char message[240];
      std::snprintf(message, sizeof message,
                    "the contact zone would be narrower than sqrt(2 R delta) = %.3g m, less than one element (%.3g m) "
                    "of the coarsest level: raise --R, --delta or --n0",
                    overlap, h);
      parser.fail(parser.given("delta") ? "delta" : parser.given("R") ? "R" : "n0", message);
    }
  }
  // a slip row multiplies a multiplier by a threshold, both of the order of E eps: E must keep
  // its square in range (the displacements do not depend on the unit of E: choose one near 1)
  for (const auto& [name, E] : {std::pair<const char*, double>{"E1", o.E1}, {"E2", o.E2}})
    if (E < 1e-100 || E > 1e100)
      parser.fail(name, "the slip rows multiply two multipliers, which scale like E: E must lie in "
                        "[1e-100, 1e100] Pa (change its unit)");
  if (o.solver == "fixed-point" && o.law == "tresca")
    parser.fail("solver", "the fixed point on Tresca thresholds solves Coulomb's law: use --law coulomb");
  parser.apply_quick(o.quick, {{"n0", o.n0, 8}, {"levels", o.levels, 3}});
  mortar::check_two_body_meshes(parser, o, o.n0, o.levels, 1.0);
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double m1 = std::max(1.0, std::round(n1 * o.H1 / o.L)), m2 = std::max(1.0, std::round(n2 * o.H2 / o.L));
  const double dofs = 2 * (n1 + 1) * (m1 + 1) + 2 * (n2 + 1) * (m2 + 1);
  if (dofs > max_dofs) {
    char message[160];
    std::snprintf(message, sizeof message, "the finest level would have about %.3g dofs, more than %.3g", dofs, max_dofs);
    parser.fail("levels", message);
  }
  const std::string memory = mortar::memory_shortfall(dofs, bytes_per_dof, mortar::machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
  mortar::prepare_output_folder(parser, o.out);
  mortar::note_nearly_incompressible(o);
}

SceneParameters scene_parameters(const Options& o) {
  SceneParameters s;
  s.name = o.scene;
  s.L = o.L;
  s.R = o.R;
  s.delta = o.delta;
  s.friction = o.friction;
  s.q_ratio = o.q_ratio;
  s.load_steps = o.load_steps;
  return s;
}

LevelSetup level_setup(const Options& o, int level) {
  LevelSetup s;
  s.geometry = mortar::two_body_geometry(o, o.n0 << level, 1.0);
  s.nonmortar = o.nonmortar - 1;
  s.law = law_of(o);
  s.friction = o.friction;
  s.fixed_point = o.solver == "fixed-point";
  return s;
}

double stick_slip_point(const FrictionalLevel& r) {
  const mortar::ContactZone z = stick_zone(r.last());
  return z.empty ? 0.0 : 0.5 * (z.right_active + z.right_inactive);
}

// The columns every row starts with: the sizes and the time against the limit.
mortar::Row level_columns(const FrictionalLevel& r) {
  return {{"h", std::max(r.h1, r.h2)},
          {"h1", r.h1},
          {"h2", r.h2},
          {"dofs", static_cast<double>(r.bodies.num_dofs())},
          {"time_s", r.time_s},
          {"limit_s", r.limit_s}};
}

// The columns of a scene with an exact solution: level_columns, then the relative errors of u
// (energy, L2) and of the pressure.
mortar::Row exact_scene_row(const FrictionalLevel& r, const mortar::ExactContact& exact) {
  mortar::ErrorNorms norms;
  const StepResult& s = r.last();
  for (int l = 0; l < 2; ++l)
    norms += mortar::error_norms(r.bodies.body(l).mesh, r.bodies.body(l).material, r.bodies.part(s.u, l), exact.exact(l));
  const auto p = [&](double x) { return exact.pressure(x); };
  mortar::Row row = level_columns(r);
  row.insert(row.end(), {{"err_energy", norms.relative_energy()},
                         {"err_l2", norms.relative_l2()},
                         {"err_pressure", mortar::l2_error(s.pressure, p) / mortar::l2_norm(s.pressure, p)}});
  return row;
}

mortar::Row manufactured_row(const FrictionalLevel& r, const mortar::ManufacturedFriction& exact) {
  const StepResult& s = r.last();
  const auto p = [&](double x) { return exact.pressure(x); };
  const auto tau = [&](double x) { return exact.shear(x); };
  const double h1 = r.gamma.nonmortar == 0 ? r.h1 : r.h2;  // of the non-mortar trace
  const double xc_error = std::fabs(stick_slip_point(r) - exact.stick_slip_point());
  int stick = 0, slip = 0;
  for (mortar::NodeStatus st : s.solution.status) {
    stick += st == mortar::NodeStatus::stick;
    slip += st == mortar::NodeStatus::slip;
  }
  mortar::Row row = exact_scene_row(r, exact);
  // against the pressure's norm: the shear's own is zero without friction
  row.push_back({"err_tangential", mortar::l2_error(s.shear, tau) / mortar::l2_norm(s.pressure, p)});
  if (exact.friction() > 0)  // without friction no node sticks, and x_c means nothing
    row.insert(row.end(), {{"stick_slip_point_error_m", xc_error}, {"stick_slip_point_error_h", xc_error / h1}});
  row.insert(row.end(), {
          {"stick_nodes", static_cast<double>(stick)},
          {"slip_nodes", static_cast<double>(slip)},
          {"newton_steps", static_cast<double>(r.newton_steps_max())},
          {"lu_steps", static_cast<double>(r.lu_steps_total())}});
  return row;
}

std::vector<CattaneoStep> compare_with_cattaneo(const Options& o, const FrictionalLevel& r, const Scene& scene) {
  std::vector<CattaneoStep> out;
  const StepResult& normal = r.steps.front();
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const StepResult& s = r.steps[k];
    CattaneoStep c;
    c.step = static_cast<int>(k);
    // Cattaneo-Mindlin at the computed forces; on the exact scene at the field's own, so that
    // the reference is the finite problem's solution
    const bool exact = k < scene.exact_steps.size();
    c.P = exact ? scene.exact_steps[k]->total_force(o.L) : s.normal_force;
    c.Q = exact ? scene.exact_steps[k]->shear_force() : s.shear_force;
    c.q_ratio = c.P > 0 ? c.Q / (o.friction * c.P) : 0.0;
    c.newton_steps = s.newton_steps;
    c.lu_steps = s.solution.lu_steps;
    c.limit_ratio = r.limit_s > 0 ? s.time_s / r.limit_s : 0.0;
    for (mortar::NodeStatus st : s.solution.status) {
      c.stick_nodes += st == mortar::NodeStatus::stick;
      c.slip_nodes += st == mortar::NodeStatus::slip;
    }
    c.c_h = stick_zone(s).half_width();
    c.pressure_change_rel_l2 = mortar::relative_l2_difference(s.pressure, normal.pressure);
    // Q of the normal step is round-off (of either sign): Cattaneo-Mindlin at Q = 0 is Hertz
    const double FP = o.friction * c.P, Q = std::fabs(c.Q) <= 1e-9 * FP ? 0.0 : c.Q;
    if (c.P > 0 && Q >= 0 && Q <= FP) {
      const CattaneoMindlin exact(c.P, Q, o.friction, e_star(o), o.R, 0.5 * o.L);
      c.c = exact.stick_half_width();
      const auto q = [&](double x) { return exact.shear(x); };
      const auto p = [&](double x) { return exact.pressure(x); };
      c.shear_rel_error_l2 = Q > 0 ? mortar::l2_error(s.shear, q) / mortar::l2_norm(s.shear, q) : 0.0;
      c.hertz_pressure_rel_error_l2 = mortar::l2_error(s.pressure, p) / mortar::l2_norm(s.pressure, p);
    } else {
      char text[200];
      std::snprintf(text, sizeof text,
                    "load step %zu: P = %.4g N/m, Q = %.4g N/m is outside Cattaneo-Mindlin's range 0 <= Q <= F P "
                    "(Q / (F P) = %.4g): lower --q-ratio",
                    k, c.P, c.Q, c.q_ratio);
      throw std::runtime_error(text);
    }
    out.push_back(c);
  }
  return out;
}

// The last columns of both Cattaneo rows: the stick zone, the pressure's change under the
// shear, the Newton and LU steps of the level.
void append_stick_zone_and_steps(mortar::Row& row, const FrictionalLevel& r, const CattaneoStep& last) {
  const double h1 = r.gamma.nonmortar == 0 ? r.h1 : r.h2;
  row.insert(row.end(), {{"stick_half_width_m", last.c_h},
                         {"stick_half_width_error_h", std::fabs(last.c_h - last.c) / h1},
                         {"pressure_change", last.pressure_change_rel_l2},
                         {"newton_steps_max", static_cast<double>(r.newton_steps_max())},
                         {"newton_steps_total", static_cast<double>(r.newton_steps_total())},
                         {"lu_steps", static_cast<double>(r.lu_steps_total())}});
}

mortar::Row cattaneo_exact_row(const FrictionalLevel& r, const mortar::CattaneoHalfPlanes& exact, const CattaneoStep& last) {
  const StepResult& s = r.last();
  const auto q = [&](double x) { return exact.shear(x); };
  mortar::Row row = exact_scene_row(r, exact);
  row.push_back({"err_tangential", mortar::l2_error(s.shear, q) / mortar::l2_norm(s.shear, q)});
  append_stick_zone_and_steps(row, r, last);
  return row;
}

mortar::Row cattaneo_row(const FrictionalLevel& r, const CattaneoStep& last) {
  mortar::Row row = level_columns(r);
  row.insert(row.end(), {{"err_tangential_traction", last.shear_rel_error_l2},
                         {"err_hertz_pressure", last.hertz_pressure_rel_error_l2},
                         {"q_ratio", last.q_ratio}});
  append_stick_zone_and_steps(row, r, last);
  return row;
}

void write_cattaneo_csv(const std::string& path, const std::vector<CattaneoStep>& steps) {
  std::ofstream out(path);
  out << "step,P,Q,q_ratio,c,c_h,shear_rel_error_l2,pressure_change_rel_l2,hertz_pressure_rel_error_l2,"
         "newton_steps,lu_steps,stick_nodes,slip_nodes,limit_ratio\n";
  char line[400];
  for (const CattaneoStep& c : steps) {
    std::snprintf(line, sizeof line, "%d,%.10g,%.10g,%.6f,%.8g,%.8g,%.6g,%.6g,%.6g,%d,%d,%d,%d,%.4g\n", c.step, c.P,
                  c.Q, c.q_ratio, c.c, c.c_h, c.shear_rel_error_l2, c.pressure_change_rel_l2,
                  c.hertz_pressure_rel_error_l2, c.newton_steps, c.lu_steps, c.stick_nodes, c.slip_nodes, c.limit_ratio);
    out << line;
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace chapter08

namespace chapter08 {

void write_newton_csv(const std::string& path, const FrictionalLevel& r) {
  std::ofstream out(path);
  out << "load_step,newton_step,residual,stick_nodes,slip_nodes\n";
  char line[160];
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const mortar::FrictionSolution& s = r.steps[k].solution;
    for (std::size_t j = 0; j < s.residuals.size(); ++j) {
      std::snprintf(line, sizeof line, "%zu,%zu,%.6e,%d,%d\n", k, j + 1, s.residuals[j], s.stick[j], s.slip[j]);
      out << line;
    }
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace chapter08
