// Chapter 5: unilateral contact, solved by Uzawa iteration and by a primal-dual active set.
//
// The bodies may now separate (paper, section 5): [u.n] <= g, lambda >= 0, lambda [u.n - g] = 0
// on Gamma_c, tested pointwise (K_h^P) or against the nonnegative basis of M_h^1 (K_h^I):
// B u <= G, one row per node or per multiplier. K is factorized once; the solvers work on the
// multipliers through S = B K^{-1} B^T (common/contact/contact_solvers.hpp).
//
//   ch05_unilateral_uzawa                                   # Hertz, integral matching, pdas
//   ch05_unilateral_uzawa --solver uzawa --acceleration none
//   ch05_unilateral_uzawa --scene partial --matching pointwise
//   ch05_unilateral_uzawa --scene bilateral                 # must agree with chapter 4
//   ch05_unilateral_uzawa --scene hertz-exact --no-compare  # Theorem 5.1 on an exact Hertz solution
#include <cstdio>
#include <exception>
#include <memory>

#include "common/study/active_sets.hpp"
#include "common/contact/exact_contact_check.hpp"
#include "common/contact/manufactured_contact.hpp"
#include "common/study/contact_plots.hpp"
#include "figures.hpp"
#include "common/study/timing_report.hpp"
#include "common/study/two_body_pictures.hpp"
#include "hertz_report.hpp"
#include "study.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  chapter05::Options o;
  mortar::OptionParser parser("ch05_unilateral_uzawa",
                              "Unilateral frictionless contact of two elastic bodies on nonmatching "
                              "meshes: Uzawa and primal-dual active set, pointwise and integral matching.");
  chapter05::parse_options(parser, o, argc, argv);
  try {
    // 2. Materials, the exact solution of the bilateral, signorini and hertz-exact scenes, and what we
    //    measure against.
    const auto exact_solution = chapter05::make_exact(
        {o.scene, o.L, o.R, o.delta}, mortar::Material(o.E1, o.nu1), mortar::Material(o.E2, o.nu2));
    const mortar::ExactContact& exact = *exact_solution;
    const chapter05::Reference ref = chapter05::make_reference(o, exact);
    const mortar::Matching matching = mortar::parse_matching(o.matching);
    const auto solver = chapter05::solver_options(o, o.solver, o.acceleration == "nesterov");

    // 3. Refine: one line per level for the chosen matching and solver.
    mortar::ConvergenceTable table;
    std::unique_ptr<chapter05::UnilateralLevel> coarsest, finest;  // kept for the pictures
    std::vector<chapter05::LevelPressure> pressures;                // every level's, for the edge
    for (int level = 0; level < o.levels; ++level) {
      auto solved = std::make_unique<chapter05::UnilateralLevel>(
          chapter05::solve_unilateral_level(chapter05::level_setup(o, level, matching, solver), exact));
      table.add(chapter05::level_row(o, *solved, ref, exact));
      pressures.push_back({solved->pressure, solved->h1, solved->h2});
      (level == 0 ? coarsest : finest) = std::move(solved);
    }

    // 4. convergence.csv, contact.csv and summary.json, before anything else can go wrong.
    const chapter05::UnilateralLevel& f = *finest;
    mortar::JsonObject results;
    results.set("h1_m", f.h1)
        .set("h2_m", f.h2)
        .set("dofs", f.bodies.num_dofs())
        .set("total_force", f.total_force)
        .set("contact_half_width", f.zone.half_width())
        .set("max_pressure", table.column("max_pressure").back())
        .set("iterations", f.solution.iterations)
        .set("columns", f.solution.columns)
        .set("complementarity_residual", f.solution.residual)
        .set("max_penetration_m", f.max_penetration)
        .set("max_penetration_x_m", f.max_penetration_x)
        .set("elements_in_contact", f.zone.active_elements)
        .set("reference", ref.kind);
    mortar::add_timing(results, f.timing);
    if (ref.kind == "hertz") chapter05::add_hertz_results(results, o, table, f, *ref.hertz);
    if (ref.kind == "exact")
      for (const std::string key : {"err_energy", "err_l2", "err_pressure", "err_pressure_hminus", "err_pressure_best",
                                    "err_total_force"})
        results.set(key, table.column(key).back());
    if (ref.kind == "exact") {
      // the exact solution against the problem itself, without any solver (exact_contact_check.hpp)
      results.set("exact_solution_check", mortar::check_exact_contact(exact, f.gap, o.L, o.H1, o.H2).worst());
      results.set("active_set_changes", f.solution.active_set_changes);
    }
    if (o.scene == "hertz-exact") {
      results.set("exact_half_width_m", chapter05::hertz_exact_half_width(o.L))
          .set("half_width_error_m", chapter05::half_width_error(f, o.L))
          .set("half_width_error_h", table.column("half_width_error_h").back())
          .set("exact_total_force", exact.total_force(o.L))
          .set("exact_max_pressure", exact.pressure(o.L / 2));
    }
    if (o.scene == "signorini") {
      results.set("contact_point_m", chapter05::computed_contact_point(f))
          .set("exact_contact_point_m", mortar::signorini_contact_point(o.L))
          .set("contact_point_error_m", chapter05::contact_point_error(f, o.L));
    }
    table.write_csv(o.out + "/convergence.csv");
    table.local_rates().write_csv(o.out + "/local_rates.csv", true);
    chapter05::write_contact_csv(o.out + "/contact.csv", f);
    mortar::write_summary(o.out + "/summary.json", parser, table.rates(), results);
    if (o.profile) mortar::report_profile(f.timing, o.out);
    std::printf("finest level: %d dofs, %d nodes in contact, total force %.6g N/m, %d iterations, "
                "residual %.2e\n", f.bodies.num_dofs(), f.zone.active_nodes, f.total_force,
                f.solution.iterations, f.solution.residual);
    if (f.penetrates() && f.zone.active_elements == 0)
      std::printf("warning: the bodies interpenetrate by up to %.3g m at x = %.4g m, yet %s: the zone "
                  "where they should touch is narrower than an element (h1 = %.3g m), and the constraints "
                  "(averages against psi_i, or values at the nodes of xi^1) do not see it; refine "
                  "(--n0, --levels) until it spans several elements\n",
                  f.max_penetration, f.max_penetration_x,
                  f.zone.empty ? "no multiplier is active" : "no element has both ends in contact", f.h1);
    if (ref.kind == "hertz") chapter05::print_hertz_errors(o, table, f, *ref.hertz);
    if (ref.kind == "exact") table.print_local_rates();
    if (o.scene == "hertz-exact")
      std::printf("half-width: exact a = %.6f m, computed %.6f m (error %.3g m = %.2f non-mortar elements), total force %.6g N/m "
                  "(exact %.6g)\n", chapter05::hertz_exact_half_width(o.L), f.zone.half_width(),
                  chapter05::half_width_error(f, o.L), table.column("half_width_error_h").back(), f.total_force,
                  exact.total_force(o.L));
    if (o.scene == "signorini")
      std::printf("contact point: exact x* = %.6f m, computed %.6f m (error %.3g m, h1 = %.3g m)\n",
                  mortar::signorini_contact_point(o.L), chapter05::computed_contact_point(f),
                  chapter05::contact_point_error(f, o.L), f.h1);
    std::printf("time %.3f s, %.2f x the physical limit (%.3f s)\n", f.time_s, f.time_s / f.limit_s, f.limit_s);
    // the finest level's active set, step by step (the active-set and Newton solvers; Uzawa has none)
    mortar::ActiveSetHistory active_sets{o.solver + ", " + mortar::matching_name(matching) + " matching", {},
                                         f.solution.active_history};
    for (int node : f.constraints.row_node) active_sets.x.push_back(f.gamma.nonmortar_trace.x[node]);
    if (!active_sets.steps.empty()) mortar::print_active_sets(active_sets);

    // 5. Every solver on both matchings, level by level: iterations, time, error.
    std::vector<chapter05::SolverRun> runs;
    std::vector<std::unique_ptr<chapter05::UnilateralLevel>> by_matching;
    if (o.compare) {
      runs = chapter05::compare_solvers(o, exact, ref, by_matching);
      chapter05::write_solver_runs(o.out + "/solvers.csv", runs);
    }

    // 6. Figures.
    const bool run = !o.no_plot;
    std::vector<const chapter05::UnilateralLevel*> shown;
    for (const auto& l : by_matching)
      if (l) shown.push_back(l.get());
    if (shown.empty()) shown.push_back(finest.get());
    chapter05::plot_pressures(o.out, o, ref, exact, shown, run);
    chapter05::plot_contact_state(o.out, o, f, run);
    if (!active_sets.steps.empty()) {
      char title[160];
      std::snprintf(title, sizeof title, "scene %s, finest level (%d dofs, h_2/h_1 = %.3g): the active set, step by step",
                    o.scene.c_str(), f.bodies.num_dofs(), o.h_ratio);
      mortar::write_active_sets(o.out, title, {active_sets}, run);
    }
    if (ref.kind == "hertz") chapter05::plot_hertz_errors(o.out, o, table, *ref.hertz, run);
    else chapter05::plot_errors(o.out, o, table, run);
    if (o.scene == "signorini" || o.scene == "hertz-exact")
      chapter05::plot_theorem_5_1(o.out, o, table, runs, run);
    if (o.scene == "hertz-exact") chapter05::plot_edge_pressure(o.out, o, exact, pressures, run);
    if (o.compare)
      chapter05::plot_solver_comparison(o.out, o, runs, ref.kind == "exact" ? "err_energy" : "err_pressure", run);

    // 7. Pictures of the problem: the coarsest level's meshes and deformed bodies, and the
    //    finest level for ParaView.
    const chapter05::UnilateralLevel& c = *coarsest;
    const std::string name = mortar::matching_name(matching) + " matching, scene " + o.scene + ", " + mortar::mesh_label(o);
    mortar::write_figure(o.out, "meshes", mortar::two_body_meshes(c.bodies, c.gamma, matching, name), run);
    mortar::write_figure(o.out, "deformed",
                         mortar::deformed_two_bodies(c.bodies, c.u, name + ", coarsest level", c.gap), run);
    mortar::write_two_body_vtu(o.out, f.bodies, f.u, f.pressure, f.jump);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch05_unilateral_uzawa: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
