#include "study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "common/contact/manufactured_contact.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/contact/pressure_norms.hpp"

#include "hertz_reference.hpp"
#include "peak_pressure.hpp"

namespace chapter05 {

namespace {
// A ceiling independent of the machine (it keeps every index far inside int);
// memory_shortfall refuses earlier wherever less than about 24 GB is free.
constexpr double max_dofs = 8'000'000;

double max_value(const mortar::InterfaceCurve& c) {
  return c.value.empty() ? 0.0 : *std::max_element(c.value.begin(), c.value.end());
}

// A P1 curve as a function of x (for errors against a reference curve).
std::function<double(double)> as_function(const mortar::InterfaceCurve& c) {
  return [&c](double x) {
    const auto it = std::upper_bound(c.x.begin(), c.x.end(), x);
    const std::size_t e = std::clamp<std::size_t>(it - c.x.begin(), 1, c.x.size() - 1) - 1;
    const double t = (x - c.x[e]) / (c.x[e + 1] - c.x[e]);
    return (1 - t) * c.value[e] + t * c.value[e + 1];
  };
}

double relative(double error, double norm) { return norm > 0 ? error / norm : 0.0; }

// Where x falls in the element of the sorted points that holds it: 0 at its left node, 1 at
// its right one (the Hertz scene: where the reference's left contact edge cuts the mesh).
double edge_in_element(const std::vector<double>& nodes, double x) {
  const auto it = std::upper_bound(nodes.begin(), nodes.end(), x);
  const std::size_t e = std::clamp<std::size_t>(it - nodes.begin(), 1, nodes.size() - 1) - 1;
  return (x - nodes[e]) / (nodes[e + 1] - nodes[e]);
}
}  // namespace

double computed_contact_point(const UnilateralLevel& r) {
  // the discrete contact zone ends halfway between its last active node and the next one
  if (r.zone.empty) return std::numeric_limits<double>::quiet_NaN();
  return 0.5 * (r.zone.right_active + r.zone.right_inactive);
}

double contact_point_error(const UnilateralLevel& r, double L) {
  return std::fabs(computed_contact_point(r) - mortar::signorini_contact_point(L));
}

double half_width_error(const UnilateralLevel& r, double L) {
  return std::fabs(r.zone.half_width() - hertz_exact_half_width(L));  // a when nothing touches
}

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  using mortar::Range;
  parser.add_choice("scene", o.scene, {"hertz", "hertz-exact", "partial", "bilateral", "signorini"}, "contact scene");
  parser.add_choice("matching", o.matching, {"integral", "pointwise"}, "how the bodies are matched on Gamma_c");
  parser.add_choice("solver", o.solver, {"pdas", "uzawa", "dual-newton"},
                    "contact solver (dual-newton: chapter 6's dual basis and semismooth Newton method, integral matching)");
  parser.add_choice("acceleration", o.acceleration, {"nesterov", "none"}, "Uzawa step: with Nesterov's momentum, or plain projected gradient");
  parser.add_choice("uzawa-step", o.uzawa_step, {"both-ends", "one-over-norm"},
                    "plain Uzawa with --rho 0: rho = 2 / (lambda_max + lambda_min(S_AA)) once the active set "
                    "settles, or 1 / ||S|| throughout");
  parser.add_double("rho", o.rho, "Uzawa step rho; 0 = automatic: 1 / ||B K^-1 B^T|| (power iteration), "
                    "for plain Uzawa then 2 / (lambda_max + lambda_min) of the active block", Range::closed(0, 1e300));
  // below 1e-14 the residual's own round-off (1e-16 to 1e-15, measured) decides whether it stops
  parser.add_double("tol", o.tol, "tolerance on the complementarity residual (relative; round-off sets the floor)",
                    Range::half_open(1e-14, 1e-2));
  parser.add_int("n0", o.n0, "body-1 elements along Gamma_c on the coarsest level (signorini: 8, hertz-exact: 4 unless given)",
                 Range::closed(2, 1 << 14));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (rates need 3; signorini: 6, hertz-exact: 7 unless given)",
                 Range::closed(3, 10));
  mortar::add_two_body_options(parser, o);
  parser.add_double("R", o.R, "radius of the Hertz gap (x - L/2)^2 / (2R) [m] (hertz-exact: sets p0 = a E* / (2R))",
                    Range::closed(1e-6, 1e12));
  parser.add_double("delta", o.delta, "downward displacement of the top of body 1 [m] (hertz and partial scenes)",
                    Range::closed(-1e6, 1e6));
  parser.add_flag("no-compare", o.no_compare, "skip the comparison of every solver on both matchings");
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets n0 = 8, levels = 3; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_flag("profile", o.profile, "print where the finest level's time goes, beside the limit's (and write profile.csv)");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, mortar::Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  o.compare = !o.no_compare;
  // the exact scenes measure local rates, which need more levels, each one cheaper
  if (o.scene == "signorini" || o.scene == "hertz-exact") {
    if (!parser.given("n0")) o.n0 = o.scene == "signorini" ? 8 : 4;
    if (!parser.given("levels")) o.levels = o.scene == "signorini" ? 6 : 7;
  }
  if (o.solver == "dual-newton" && o.matching != "integral")
    parser.fail("solver", "dual-newton is chapter 6's method on the dual basis of M_h^1: integral matching only");
  parser.apply_quick(o.quick, {{"n0", o.n0, 8}, {"levels", o.levels, 3}});  // after the scene's defaults
  mortar::check_two_body_meshes(parser, o, o.n0, o.levels, 1.0);  // square cells
  // small displacements: the imposed one must be small against the body it compresses
  // (only the scenes pressed between plates use it)
  if ((o.scene == "hertz" || o.scene == "partial") && std::fabs(o.delta) >= o.H1)
    parser.fail("delta", "|delta| = " + std::to_string(std::fabs(o.delta)) + " m is not small against the height of "
                "body 1, H1 = " + std::to_string(o.H1) + " m: linear elasticity needs |delta| < H1");
  // S = B K^-1 B^T scales like 1/E; beyond these bounds its squares leave the range of double
  // (the answer does not depend on the unit of E: choose one that brings E near 1)
  for (const auto& [name, E] : {std::pair<const char*, double>{"E1", o.E1}, {"E2", o.E2}})
    if (E < 1e-100 || E > 1e100)
      parser.fail(name, "the contact solvers work on B K^-1 B^T, which scales like 1/E: E must lie in "
                        "[1e-100, 1e100] Pa (the displacements do not depend on the unit of E; change it)");
  mortar::check_stiffness_ratio(parser, o);
  mortar::choose_softer_nonmortar(parser, o);
  // Sizes in floating point, so that no product can overflow before it is compared; the
  // meshes are those of two_body_geometry with square cells.
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double m1 = std::max(1.0, std::round(n1 * o.H1 / o.L)), m2 = std::max(1.0, std::round(n2 * o.H2 / o.L));
  const double dofs = 2 * (n1 + 1) * (m1 + 1) + 2 * (n2 + 1) * (m2 + 1);
  // the partial scene solves two levels finer for its reference (16 times the dofs); the
  // Hertz scene's graded reference has about as many dofs as the finest level (82,716 against
  // 107,780 by default). Measured peaks (/usr/bin/time -v): Hertz 0.42 GB at 107,780 finest
  // dofs (with the comparison of solvers) and 1.49 GB at about 428,000, i.e. 1.9 and 1.7 kB
  // per counted dof; partial 5.71 GB at 107,780 (1.72M reference dofs), 3.3 kB per counted
  // dof: the unilateral reference needs more than one Cholesky solve, hence 3.5 kB.
  constexpr double bytes_per_counted_dof = 3500;
  const double reference_factor = o.scene == "partial" ? 16 : o.scene == "hertz" ? 2 : 1;
  if (dofs * reference_factor > max_dofs) {
    char message[160];
    std::snprintf(message, sizeof message, "the finest level would have about %.3g dofs (with its reference), more than %.3g",
                  dofs * reference_factor, max_dofs);
    parser.fail("levels", message);
  }
  // The contact solvers work on S = B K^-1 B^T, dense on Gamma_c (its active block and its
  // factor too): counted on the finest level, and on the partial scene's reference, whose
  // Gamma_c has 4 times the nodes.
  const double line_factor = o.scene == "partial" ? 4 : 1;
  const double m = line_factor * (o.nonmortar == 1 ? n1 : n2) - 1, t = line_factor * (o.nonmortar == 1 ? n2 : n1) + 1;
  char sparse[96], dense[160];
  std::snprintf(sparse, sizeof sparse, "the sparse solves (%.3g dofs with the reference)", dofs * reference_factor);
  std::snprintf(dense, sizeof dense, "S = B K^-1 B^T, its active block and the factor's dense block on Gamma_c "
                "(%.0f multipliers, %.0f mortar nodes)", m, t);
  const std::string memory = mortar::memory_shortfall(
      {{sparse, dofs * reference_factor * bytes_per_counted_dof},
       {dense, mortar::schur_dense_bytes(m, t) + mortar::dense_bytes(m, m)}},
      mortar::machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
  mortar::prepare_output_folder(parser, o.out);
  mortar::note_nearly_incompressible(o);
  // accepted (|delta| < H1), but a strain of more than a few percent is not the small strain
  // linear elasticity assumes
  if ((o.scene == "hertz" || o.scene == "partial") && std::fabs(o.delta) > 0.05 * o.H1)
    std::printf("note: delta = %g m compresses body 1 by %.3g%% of its height: linear elasticity assumes small "
                "strains, so read the answer as that model's, not as the bodies'\n",
                o.delta, 100 * std::fabs(o.delta) / o.H1);
}

mortar::ContactSolverOptions solver_options(const Options& o, const std::string& solver, bool accelerate) {
  mortar::ContactSolverOptions s;
  s.kind = mortar::parse_contact_solver(solver == "dual-newton" ? "pdas" : solver);
  s.accelerate = accelerate;
  s.tol = o.tol;
  s.rho = o.rho;
  s.step_from_both_ends = o.uzawa_step == "both-ends";
  return s;
}

UnilateralSetup level_setup(const Options& o, int level, mortar::Matching matching,
                            const mortar::ContactSolverOptions& solver) {
  UnilateralSetup s;
  s.geometry = mortar::two_body_geometry(o, o.n0 << level, 1.0);  // square cells
  s.matching = matching;
  s.nonmortar = o.nonmortar - 1;
  s.solver = solver;
  s.scene = {o.scene, o.L, o.R, o.delta};
  s.dual_newton = o.solver == "dual-newton";
  return s;
}

Reference make_reference(const Options& o, const mortar::ExactContact& exact) {
  Reference ref;
  if (o.scene == "hertz") {
    ref.kind = "hertz";
    ref.hertz = std::make_shared<const HertzReference>(make_hertz_reference(o, exact, reference_grading(o)));
  }
  if (o.scene == "bilateral" || o.scene == "signorini" || o.scene == "hertz-exact") ref.kind = "exact";
  if (o.scene == "partial") {
    ref.kind = "finer mesh";
    // two levels beyond the finest, integral matching, active set: the best we can afford
    ref.finer = std::make_unique<UnilateralLevel>(solve_unilateral_level(
        level_setup(o, o.levels + 1, mortar::Matching::integral, solver_options(o, "pdas", true)), exact));
  }
  return ref;
}

Hertz hertz_for(const Options& o, const UnilateralLevel& r) {
  return hertz_at_force(o.E1, o.nu1, o.E2, o.nu2, o.R, r.total_force);
}

mortar::Row level_row(const Options& o, const UnilateralLevel& r, const Reference& ref,
                      const mortar::ExactContact& exact) {
  mortar::Row row = {{"h", std::max(r.h1, r.h2)},
                     {"h1", r.h1},
                     {"h2", r.h2},
                     {"dofs", static_cast<double>(r.bodies.num_dofs())},
                     {"multipliers", static_cast<double>(r.solution.lambda.size())},
                     {"nodes_in_contact", static_cast<double>(r.zone.active_nodes)},
                     {"iterations", static_cast<double>(r.solution.iterations)},
                     {"columns", static_cast<double>(r.solution.columns)},
                     {"time_s", r.time_s},
                     {"limit_s", r.limit_s},
                     {"total_force", r.total_force},
                     {"half_width", r.zone.half_width()},
                     {"max_pressure", max_value(r.pressure)},
                     {"complementarity_residual", r.solution.residual}};
  if (ref.kind == "hertz") {
    // Discretization error: against the finite-body reference (hertz_reference.hpp).
    const HertzReference& fb = *ref.hertz;
    const double c = o.L / 2, peak = peak_pressure(r.pressure, c), a = r.zone.half_width();
    row.push_back({"centre_pressure", pressure_at(r.pressure, c)});
    row.push_back({"peak_pressure", peak});
    row.push_back({"edge_offset_elements", edge_offset_in_elements(r.zone, fb.zone, r.gamma.nonmortar_trace.max_element_length())});
    row.push_back({"edge_in_element", edge_in_element(r.pressure.x, c - fb.half_width.value)});
    row.push_back({"err_pressure", relative_l2_distance(r.pressure, fb.pressure)});
    // the part of it on the central half of the zone, away from the square-root edges
    const double a_ref = fb.half_width.value;
    row.push_back({"err_pressure_centre", relative_l2_distance_on(r.pressure, fb.pressure, c - a_ref / 2, c + a_ref / 2)});
    row.push_back({"err_peak_pressure", relative(std::fabs(peak - fb.peak.value), fb.peak.value)});
    row.push_back({"err_half_width", relative(std::fabs(a - fb.half_width.value), fb.half_width.value)});
    row.push_back({"err_total_force", relative(std::fabs(r.total_force - fb.force.value), fb.force.value)});
    // Distance to half-space Hertz at this level's force, signed: model error and
    // discretization error together.
    const Hertz h = hertz_for(o, r);
    const auto p = [&](double x) { return h.pressure(x - c); };
    row.push_back({"hertz_distance_pressure", relative(mortar::l2_error(r.pressure, p), mortar::l2_norm(r.pressure, p))});
    row.push_back({"hertz_distance_peak", relative(peak - h.peak_pressure(), h.peak_pressure())});
    row.push_back({"hertz_distance_half_width", relative(a - h.half_width(), h.half_width())});
  } else if (ref.kind == "exact") {
    // the computed u, and beside it the nodal interpolant of the exact u on the same meshes:
    // what the meshes allow, whatever the contact does
    mortar::ErrorNorms norms, interpolant;
    for (int l = 0; l < 2; ++l) {
      const mortar::Mesh& mesh = r.bodies.body(l).mesh;
      norms += mortar::error_norms(mesh, r.bodies.body(l).material, r.bodies.part(r.u, l), exact.exact(l));
      Eigen::VectorXd u_i(mesh.num_dofs());
      for (int a = 0; a < mesh.num_nodes(); ++a) u_i.segment<2>(2 * a) = exact.u(l, mesh.nodes[a]);
      interpolant += mortar::error_norms(mesh, r.bodies.body(l).material, u_i, exact.exact(l));
    }
    const auto p = [&](double x) { return exact.pressure(x); };
    const auto jump = [&](double x) { return exact.normal_jump(x); };
    const auto u1_y = [&](double x) { return exact.u(0, {x, 0.0}).y(); };
    // the multiplier in its own norms (common/contact/pressure_norms.hpp): L2, the mesh-dependent
    // H^{-1/2} norm, and the L2 best approximation in M_h^1 beside them
    const mortar::PressureErrors pe = mortar::pressure_errors(r.gamma, r.pressure, p, exact.pressure_kinks());
    row.push_back({"err_energy", norms.relative_energy()});
    row.push_back({"err_energy_interpolant", interpolant.relative_energy()});
    row.push_back({"err_l2", norms.relative_l2()});
    row.push_back({"err_pressure", relative(pe.l2, pe.norm_l2)});
    row.push_back({"err_pressure_hminus", relative(pe.hminus, pe.norm_hminus)});
    row.push_back({"err_pressure_best", relative(pe.best_l2, pe.norm_l2)});
    // the jump against the exact one, relative to the normal displacement of body 1 on Gamma_c
    row.push_back({"err_jump", relative(mortar::l2_error(r.jump, jump), mortar::l2_norm(r.jump, u1_y))});
    const double force = exact.total_force(o.L);
    row.push_back({"err_total_force", relative(std::fabs(r.total_force - force), force)});
    if (o.scene == "signorini") row.push_back({"err_contact_point", contact_point_error(r, o.L)});
    if (o.scene == "hertz-exact") {
      // the half-width in metres and in elements of the non-mortar side (a rate of it means
      // nothing: it depends on where the edges fall between two nodes)
      const double error = half_width_error(r, o.L);
      row.push_back({"half_width_error_m", error});
      row.push_back({"half_width_error_h", error / r.gamma.nonmortar_trace.max_element_length()});
    }
    row.push_back({"active_set_changes", static_cast<double>(r.solution.active_set_changes)});
  } else {
    const auto p = as_function(ref.finer->pressure);
    row.push_back({"err_pressure", relative(mortar::l2_error(r.pressure, p), mortar::l2_norm(r.pressure, p))});
    row.push_back({"err_total_force", relative(std::fabs(r.total_force - ref.finer->total_force), ref.finer->total_force)});
  }
  return row;
}

std::vector<SolverRun> compare_solvers(const Options& o, const mortar::ExactContact& exact,
                                       const Reference& ref,
                                       std::vector<std::unique_ptr<UnilateralLevel>>& finest_by_matching) {
  struct Variant {
    std::string label, solver;
    bool accelerate;
    mortar::SpdBackend backend;
    bool dual_newton = false;
  };
  // The same answer four ways: the active set, Uzawa with and without momentum (all on the
  // fastest Cholesky), and the active set on Eigen's readable SimplicialLDLT. A fifth for
  // integral matching: chapter 6's dual basis and semismooth Newton method (a nearby discrete
  // problem, the weighted gap, from an empty first active set).
  const mortar::SpdBackend fast = mortar::fastest_spd_backend(), readable = mortar::SpdBackend::simplicial_ldlt;
  const Variant variants[] = {{"pdas", "pdas", true, fast},
                              {"uzawa-nesterov", "uzawa", true, fast},
                              {"uzawa", "uzawa", false, fast},
                              {"pdas-simplicial-ldlt", "pdas", true, readable},
                              {"dual-newton", "pdas", true, fast, true}};
  std::vector<SolverRun> runs;
  finest_by_matching.clear();
  for (const std::string matching : {"integral", "pointwise"}) {
    std::unique_ptr<UnilateralLevel> finest;
    for (int level = 0; level < o.levels; ++level)
      for (const Variant& v : variants) {
        if (v.dual_newton && matching != "integral") continue;
        mortar::ContactSolverOptions solver = solver_options(o, v.solver, v.accelerate);
        solver.backend = v.backend;
        std::unique_ptr<UnilateralLevel> r;
        try {
          // each variant at each level: one timing of it and of its limit (the study's own
          // finest level is the one timed with repetitions)
          UnilateralSetup setup = level_setup(o, level, mortar::parse_matching(matching), solver);
          setup.repetitions = {1, 1, 0.0};
          setup.dual_newton = v.dual_newton;
          r = std::make_unique<UnilateralLevel>(solve_unilateral_level(setup, exact));
        } catch (const std::runtime_error& e) {
          // one solver failing must not cost the others' results: say so and go on
          std::printf("compare: %-9s %-20s level %d  failed: %s\n", matching.c_str(), v.label.c_str(), level, e.what());
          continue;
        }
        const mortar::Row row = level_row(o, *r, ref, exact);
        SolverRun run{matching, v.label, level, std::max(r->h1, r->h2), r->time_s, r->limit_s, 0,
                      r->total_force, r->solution.iterations, r->solution.columns};
        for (const auto& [name, value] : row)
          if (name == (ref.kind == "exact" ? "err_energy" : "err_pressure")) run.error = value;
        runs.push_back(run);
        std::printf("compare: %-9s %-20s level %d  iterations %6d  columns %4d  time %.3f s  error %.3e\n",
                    matching.c_str(), v.label.c_str(), level, run.iterations, run.columns, run.time_s, run.error);
        if (level == o.levels - 1 && v.label == "pdas") finest = std::move(r);
      }
    finest_by_matching.push_back(std::move(finest));
  }
  return runs;
}

void write_solver_runs(const std::string& path, const std::vector<SolverRun>& runs) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << "matching,solver,level,h,iterations,columns,time_s,limit_s,error,total_force\n";
  for (const SolverRun& r : runs)
    f << r.matching << "," << r.solver << "," << r.level << "," << r.h << "," << r.iterations << ","
      << r.columns << "," << r.time_s << "," << r.limit_s << "," << r.error << "," << r.total_force << "\n";
}

}  // namespace chapter05
