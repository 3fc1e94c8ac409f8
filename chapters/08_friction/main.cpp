// Chapter 8: friction. Chapter 6's dual basis makes every contact condition nodal; friction adds
// a second one per node, in the tangential direction: stick (no slip, |lambda_t| < s) or slip
// (|lambda_t| = s, in the slip's direction), with s Tresca's given threshold or Coulomb's
// F lambda_n. Both conditions are written as nodal equations C = 0 and solved together by a
// semismooth Newton method in the displacements (common/contact/friction_newton.hpp).
//
//   ch08_friction                                   # manufactured scene, Coulomb, errors against h
//   ch08_friction --law tresca                      # the same exact solution, Tresca's threshold F p
//   ch08_friction --scene cattaneo                  # normal load, then shear in 10 steps: Cattaneo-Mindlin
//   ch08_friction --scene cattaneo --q-ratio 0.95   # a stick zone of a few elements
//   ch08_friction --scene cattaneo-exact            # the same path, exact: local rates of the shear
#include <algorithm>
#include <cstdio>
#include <exception>

#include "common/contact/exact_contact_check.hpp"
#include "common/study/timing_report.hpp"
#include "comparisons.hpp"
#include "figures.hpp"
#include "study.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  chapter08::Options o;
  mortar::OptionParser parser("ch08_friction",
                              "Frictional contact (Tresca, Coulomb) of two elastic bodies with dual mortar multipliers and a "
                              "semismooth Newton method, against an exact solution and against Cattaneo-Mindlin.");
  chapter08::parse_options(parser, o, argc, argv);
  try {
    const mortar::Material m1(o.E1, o.nu1), m2(o.E2, o.nu2);
    // 2. The exact solution (manufactured scene; the cattaneo scene reads only the materials).
    const mortar::ManufacturedFriction exact(m1, m2, o.L, o.friction);
    const chapter08::Scene scene = chapter08::make_scene(chapter08::scene_parameters(o), exact);

    // 3. Refine: each level runs the scene's whole load path.
    mortar::ConvergenceTable table;
    std::unique_ptr<chapter08::FrictionalLevel> finest;
    std::vector<chapter08::CattaneoStep> cattaneo;
    for (int level = 0; level < o.levels; ++level) {
      chapter08::LevelSetup setup = chapter08::level_setup(o, level);
      if (finest && o.start == "nested") setup.start_at = chapter08::nested_start(*finest);
      auto r = std::make_unique<chapter08::FrictionalLevel>(chapter08::solve_frictional_level(setup, scene, m1, m2));
      if (level == 0) chapter08::plot_meshes(o.out, *r, o, !o.no_plot);  // the bodies, before any result
      if (o.scene == "manufactured") {
        table.add(chapter08::manufactured_row(*r, exact));
      } else {
        cattaneo = chapter08::compare_with_cattaneo(o, *r, scene);
        table.add(scene.exact_steps.empty() ? chapter08::cattaneo_row(*r, cattaneo.back())
                                            : chapter08::cattaneo_exact_row(*r, *scene.exact_steps.back(), cattaneo.back()));
      }
      finest = std::move(r);
    }
    const chapter08::FrictionalLevel& f = *finest;

    // 4. convergence.csv, local_rates.csv and summary.json.
    mortar::JsonObject results;
    results.set("h1_m", f.h1).set("h2_m", f.h2).set("dofs", f.bodies.num_dofs())
        .set("newton_steps_max", f.newton_steps_max())
        .set("newton_steps_total", f.newton_steps_total())
        .set("lu_steps", f.lu_steps_total())
        .set("load_steps", static_cast<int>(f.steps.size()))
        .set("time_per_newton_step_limit_ratio", f.time_s / f.newton_steps_total() / f.limit_s);
    mortar::add_timing(results, f.timing);  // limit_ratio, limit_s, spreads, memory peaks
    if (o.scene == "manufactured") {
      for (const std::string key : {"err_energy", "err_l2", "err_pressure", "err_tangential"})
        results.set(key, table.column(key).back());
      if (o.friction > 0)
        results.set("stick_slip_point_m", chapter08::stick_slip_point(f))
            .set("exact_stick_slip_point_m", exact.stick_slip_point())
            .set("stick_slip_point_error_m", table.column("stick_slip_point_error_m").back())
            .set("stick_slip_point_error_h", table.column("stick_slip_point_error_h").back());
    } else {
      const chapter08::CattaneoStep& c = cattaneo.back();
      const double h1 = f.gamma.nonmortar == 0 ? f.h1 : f.h2;
      results.set("normal_force", c.P).set("shear_force", c.Q).set("q_ratio", c.q_ratio)
          .set("stick_half_width_m", c.c_h).set("exact_stick_half_width_m", c.c)
          .set("stick_half_width_error_m", std::fabs(c.c_h - c.c))
          .set("stick_half_width_error_h", std::fabs(c.c_h - c.c) / h1)
          .set("tangential_traction_rel_error_l2", c.shear_rel_error_l2)
          .set("hertz_pressure_rel_error_l2", c.hertz_pressure_rel_error_l2)
          .set("pressure_change_rel_l2", c.pressure_change_rel_l2);
      if (!scene.exact_steps.empty()) {  // the field against the problem itself, without any solver
        for (const std::string key : {"err_energy", "err_l2", "err_pressure", "err_tangential"})
          results.set(key, table.column(key).back());
        results.set("exact_solution_check",
                    mortar::check_exact_contact(*scene.exact_steps.back(), scene.gap, o.L, o.H1, o.H2).worst());
      }
      chapter08::write_cattaneo_csv(o.out + "/cattaneo.csv", cattaneo);
    }
    chapter08::write_newton_csv(o.out + "/newton.csv", f);
    table.write_csv(o.out + "/convergence.csv");
    table.local_rates().write_csv(o.out + "/local_rates.csv", true);
    mortar::write_summary(o.out + "/summary.json", parser, table.rates(), results);
    table.print_local_rates();
    std::printf("finest level: %d dofs, %d load steps, at most %d Newton steps per load step (%d with an LU), "
                "time %.3f s = %.2f x the physical limit (%.3f s)\n",
                f.bodies.num_dofs(), static_cast<int>(f.steps.size()), f.newton_steps_max(), f.lu_steps_total(),
                f.time_s, f.time_s / f.limit_s, f.limit_s);

    // 5. Beside the study: Newton against the fixed point (manufactured, Coulomb), or the load
    //    paths (cattaneo), on the level below the finest (a quarter of its cost).
    //    The solvers up to level 4 at most (24k dofs by default): the fixed point takes up to 15
    //    Tresca problems per level.
    const int compared_level = std::max(0, o.levels - 2);
    if (!o.no_compare && o.scene == "manufactured" && o.law == "coulomb")
      chapter08::write_solver_runs(o.out + "/solvers.csv", chapter08::compare_solvers(o, {0.1, 0.2, 0.3, 0.5, 1.0},
                                                                                      std::min(compared_level, 4)));
    if (!o.no_compare && o.scene == "cattaneo")
      chapter08::write_path_runs(o.out + "/paths.csv", chapter08::compare_paths(o, compared_level));

    // 6. Figures.
    const bool run = !o.no_plot;
    chapter08::ExactCurves curves;
    if (o.scene == "manufactured") {
      curves = {[&](double x) { return exact.shear(x); }, [&](double x) { return exact.threshold(x); },
                "exact shear τ", 0, 0};
    } else {
      const chapter08::CattaneoStep& c = cattaneo.back();  // the exact field's P and Q on cattaneo-exact
      const chapter08::CattaneoMindlin cm(c.P, c.Q, o.friction, chapter08::e_star(o), o.R, 0.5 * o.L);
      curves = {[cm](double x) { return cm.shear(x); }, {}, "Cattaneo-Mindlin q(x) at the computed P, Q",
                0.5 * o.L - 1.4 * cm.half_width(), 0.5 * o.L + 1.4 * cm.half_width()};
      chapter08::plot_stick_zone(o.out, o, cattaneo, cm.half_width(), run);
    }
    chapter08::plot_zones(o.out, f, o, curves, run);
    chapter08::plot_errors(o.out, table, o, run);
    chapter08::plot_newton(o.out, o, f, run);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch08_friction: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
