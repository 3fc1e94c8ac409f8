// Chapter 11: contact without multipliers. Nitsche's method (Chouly and Hild 2013) and penalty
// against chapter 5's integral mortar and chapter 6's dual basis, head to head on chapter 5's
// exact Hertz solution: every method on the same meshes, measured against the same exact u and p.
//
//   ch11_nitsche_contact                          # theta = 1, gamma0 = 5, body 1's traction
//   ch11_nitsche_contact --theta -1 --gamma0 1e-3 # skew-symmetric: stable for any gamma0
//   ch11_nitsche_contact --h-ratio 1/3            # the other mesh ratio
//   ch11_nitsche_contact --sweep gamma0           # errors and Newton steps against gamma0
//   ch11_nitsche_contact --sweep stiffness        # E1/E2 = 1e-6 .. 1e6, each body's traction
#include <cmath>
#include <cstdio>
#include <exception>

#include "figures.hpp"
#include "options.hpp"
#include "patch_test.hpp"
#include "study.hpp"
#include "common/study/json_writer.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  chapter11::Options o;
  mortar::OptionParser parser("ch11_nitsche_contact",
                              "Contact without multipliers: Nitsche (theta = 1, 0, -1) and penalty against integral "
                              "mortar and the dual basis on the exact Hertz solution.");
  chapter11::parse_options(parser, o, argc, argv);
  try {
    // 2. The exact solution and every level, every method.
    const chapter11::Scene scene = chapter11::make_scene(o);
    mortar::ConvergenceTable table;
    std::vector<chapter11::Level> levels;
    levels.reserve(o.levels);  // solve_level reads the level below by address
    for (int k = 0; k < o.levels; ++k) {
      levels.push_back(chapter11::make_level(o, scene, k));
      chapter11::solve_level(o, scene, levels.back(), k > 0 ? &levels[k - 1] : nullptr);
      table.add(chapter11::level_row(levels.back()));
    }
    // 3. convergence.csv, local_rates.csv, summary.json.
    table.write_csv(o.out + "/convergence.csv", true);  // Krylov iterations not counted: blank
    const mortar::ConvergenceTable local = table.local_rates();
    local.write_csv(o.out + "/local_rates.csv", true);
    table.print_local_rates();
    const chapter11::Level& finest = levels.back();
    mortar::JsonObject results;
    results.set("dofs", finest.bodies.num_dofs()).set("limit_s", finest.limit_s);
    for (const chapter11::MethodResult& r : finest.methods) {
      if (r.name != "mortar" && r.name != "dual")
        results.set("newton_residual_" + r.name, r.residual).set("lu_fallback_steps_" + r.name, r.lu_fallbacks);
      results.set("newton_steps_" + r.name, r.newton_steps)
          .set("converged_" + r.name, r.converged)
          .set("err_energy_" + r.name, r.err_energy)
          .set("err_pressure_" + r.name, r.err_pressure)
          .set("half_width_error_m_" + r.name, r.half_width_error_m)
          .set("total_force_" + r.name, r.total_force)
          .set("limit_ratio_" + r.name, r.time_s / finest.limit_s);
    }
    results.set("limit_ratio", finest.methods.front().time_s / finest.limit_s)
        .set("exact_total_force", scene.exact->total_force(o.L))
        .set("nitsche_solver", finest.methods.front().solver);
    // 4. The patch test of each method without multipliers, and the gamma0 sweep.
    for (const std::string m : {"nitsche", "penalty", "penalty_fixed"}) {
      const chapter11::PatchResult patch = chapter11::nitsche_patch_test(o, chapter11::method_options(o, m));
      results.set("patch_test_rel_error_" + m, patch.rel_error);
      if (std::isfinite(patch.rel_error))
        std::printf("patch test, %s: max |sigma_22 + p| / p = %.3g (%d Newton steps)\n", m.c_str(), patch.rel_error,
                    patch.newton_steps);
      else
        std::printf("patch test, %s: Newton did not converge in %d steps\n", m.c_str(), patch.newton_steps);
    }
    std::vector<chapter11::SweepPoint> sweep;
    if (o.sweep == "gamma0") {
      sweep = chapter11::gamma_sweep(o, scene, levels[o.sweep_level]);
      chapter11::write_sweep(o.out + "/gamma_sweep.csv", sweep);
    }
    std::vector<chapter11::StiffnessPoint> stiffness;
    if (o.sweep == "stiffness") {
      stiffness = chapter11::stiffness_sweep(o);
      chapter11::write_stiffness_sweep(o.out + "/stiffness_sweep.csv", stiffness);
    }
    mortar::write_summary(o.out + "/summary.json", parser, table.rates(), results);
    std::printf("finest level (%d dofs): physical limit %.3f s;", finest.bodies.num_dofs(), finest.limit_s);
    for (const chapter11::MethodResult& r : finest.methods)
      std::printf(" %s %.2f x", r.name.c_str(), r.time_s / finest.limit_s);
    std::printf("\n");
    // 5. Figures.
    chapter11::write_figures(o, table, levels, scene, sweep, stiffness, !o.no_plot);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch11_nitsche_contact: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
