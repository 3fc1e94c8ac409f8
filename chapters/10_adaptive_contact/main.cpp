// Chapter 10: where the error lives. A residual a posteriori estimator for two-body contact,
// Doerfler marking and newest-vertex bisection, each body refined on its own mesh; the mortar
// method glues whatever traces the two meshes leave on Gamma_c.
//
// The loop SOLVE -> ESTIMATE -> MARK -> REFINE (adaptive_loop.hpp) runs until the estimated
// relative energy error is below --target; beside it, uniform refinement with the same solver
// until the true error is below --uniform-target. Where the exact solution is known (hertz-exact,
// bilateral) every step reports the effectivity eta / ||u - u_h||; the punch has none, and is
// measured against the extrapolated strain energy (study.hpp).
//
//   ch10_adaptive_contact                           # hertz-exact, zone half-width 0.049 L
//   ch10_adaptive_contact --target 0.001 --no-uniform  # 0.1 %, which uniform meshes cannot reach here
//   ch10_adaptive_contact --scene punch             # singular corners: rates in N, both ways
//   ch10_adaptive_contact --scene bilateral         # smooth: adaptivity should refine almost uniformly
#include <cmath>
#include <cstdio>
#include <exception>

#include "figures.hpp"
#include "options.hpp"
#include "study.hpp"
#include "wedge_exponent.hpp"
#include "common/contact/bilateral_contact.hpp"
#include "common/linalg/physical_limit.hpp"

namespace {

using chapter10::LoopResult;

void print_comparison(const LoopResult& adaptive, const LoopResult* uniform) {
  std::printf("adaptive: %zu steps (%s); rates in N (last factor 16 in N): error %.3f, estimator %.3f\n",
              adaptive.steps.size(), adaptive.stopped_because.c_str(), chapter10::rate_in_n(adaptive, "error"),
              chapter10::rate_in_n(adaptive, "estimator"));
  if (uniform != nullptr)
    std::printf("uniform:  %zu levels (%s); rates in N (last factor 16 in N): error %.3f, estimator %.3f\n",
                uniform->steps.size(), uniform->stopped_because.c_str(), chapter10::rate_in_n(*uniform, "error"),
                chapter10::rate_in_n(*uniform, "estimator"));
}

// effectivity over every step of both runs: its smallest and largest value
std::pair<double, double> effectivity_band(const LoopResult& a, const LoopResult* u) {
  double lo = INFINITY, hi = 0;
  for (const LoopResult* run : {&a, u})
    if (run != nullptr)
      for (const auto& r : run->steps) {
        lo = std::min(lo, r.effectivity);
        hi = std::max(hi, r.effectivity);
      }
  return {lo, hi};
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  chapter10::Options o;
  mortar::OptionParser parser("ch10_adaptive_contact",
                              "Adaptive mortar contact: a residual a posteriori estimator, Doerfler marking and "
                              "newest-vertex bisection of each body, against uniform refinement.");
  chapter10::parse_options(parser, o, argc, argv);
  try {
    const chapter10::Scene scene(o.scene);
    const bool punch = o.scene.name == "punch";
    // 2. The adaptive loop; the punch's runs on past --target, for its reference (study.hpp).
    chapter10::LoopOptions loop = o.loop;
    if (punch) loop.target = o.loop.target / 2;
    LoopResult adaptive = chapter10::run_adaptive_loop(scene, loop);
    const chapter10::StepRecord finest = adaptive.steps.back();  // the last solve's step
    chapter10::EnergyReference reference;
    if (punch) {
      reference = chapter10::split_off_reference(adaptive, o.loop.target);
      chapter10::measure_against_reference(adaptive, reference);
      std::printf("punch: strain energy extrapolated from %d further steps (%d to %d dofs) W = %.10g (finest step "
                  "%.10g); the table's %zu steps end at %d dofs\n",
                  reference.steps_fitted, reference.dofs_from, reference.dofs_to, reference.W, reference.W_finest,
                  adaptive.steps.size(), adaptive.steps.back().dofs);
    }
    // 3. Uniform refinement with the same solver.
    std::unique_ptr<LoopResult> uniform;
    if (!o.no_uniform) {
      uniform = std::make_unique<LoopResult>(chapter10::run_uniform_levels(scene, o.loop, o.uniform_target));
      if (punch) chapter10::measure_against_reference(*uniform, reference);
    }
    // 4. The physical limit of the last mesh solved.
    const chapter10::ContactStep& last = *adaptive.last;
    const double limit_s = mortar::two_body_limit(last.bodies, scene.data(last.bodies));
    const chapter10::StepRecord& final_step = adaptive.steps.back();

    // 5. convergence.csv (adaptive steps), uniform.csv, summary.json.
    const mortar::ConvergenceTable table = chapter10::step_table(adaptive);
    table.write_csv(o.out + "/convergence.csv");
    if (uniform) chapter10::step_table(*uniform).write_csv(o.out + "/uniform.csv");
    mortar::JsonObject results;
    const auto [eff_lo, eff_hi] = effectivity_band(adaptive, uniform.get());
    results.set("steps", static_cast<int>(adaptive.steps.size()))
        .set("dofs", final_step.dofs)
        .set("err_energy_rel", final_step.rel_err_energy)
        .set("estimator_rel", final_step.rel_estimator)
        .set("min_angle_deg", final_step.min_angle_deg)
        .set("newton_steps_last", final_step.newton_steps)
        .set("rate_in_n_adaptive", chapter10::rate_in_n(adaptive, "error"))
        .set("estimator_rate_in_n_adaptive", chapter10::rate_in_n(adaptive, "estimator"));
    if (!punch)
      results.set("effectivity_min", eff_lo).set("effectivity_max", eff_hi).set("effectivity_ratio", eff_hi / eff_lo);
    if (uniform) {
      const double ta = chapter10::time_to_error(adaptive, 0.01), tu = chapter10::time_to_error(*uniform, 0.01);
      results.set("rate_in_n_uniform", chapter10::rate_in_n(*uniform, "error"))
          .set("uniform_levels", static_cast<int>(uniform->steps.size()))
          .set("uniform_dofs_max", uniform->steps.back().dofs)
          .set("uniform_err_energy_rel_min", uniform->steps.back().rel_err_energy)
          .set("time_to_1pct_adaptive_s", ta)
          .set("time_to_1pct_uniform_s", tu)
          .set("speedup_at_1pct", tu / ta)
          .set("dofs_at_1pct_adaptive", chapter10::dofs_at_error(adaptive, 0.01))
          .set("dofs_at_1pct_uniform", chapter10::dofs_at_error(*uniform, 0.01));
    }
    if (punch) {
      const double w = o.scene.bodies.L / 4, corner = o.scene.bodies.L / 2 - w / 2;
      const double alpha = chapter10::dundurs_alpha(o.scene.bodies.E1, o.scene.bodies.nu1, o.scene.bodies.E2, o.scene.bodies.nu2);
      const double lambda = chapter10::wedge_on_half_plane_exponent(alpha, std::acos(-1.0) / 2);
      const double measured = chapter10::pressure_exponent(last, corner, 16 * finest.h_min, w / 16);
      results.set("reference_strain_energy", reference.W)
          .set("finest_strain_energy", reference.W_finest)
          .set("reference_steps", reference.steps_fitted)
          .set("reference_dofs_max", reference.dofs_to)
          .set("pressure_exponent_measured", measured)
          .set("pressure_exponent_theory", lambda - 1)
          .set("dundurs_alpha", alpha);
      if (std::isfinite(measured))
        std::printf("punch corner: pressure ~ r^s with s = %.4f measured on the last mesh (r from %.3g to %.3g m), ",
                    measured, 16 * finest.h_min, w / 16);
      else
        std::printf("punch corner: s not measured (no nodes from 16 h_min = %.3g to %.3g m of the corner), ",
                    16 * finest.h_min, w / 16);
      std::printf("%.4f from the wedge-on-half-plane equation (alpha = %.4f): uniform meshes should converge like "
                  "N^-%.3f, adaptive ones like N^-0.5\n",
                  lambda - 1, alpha, lambda / 2);
    }
    results.set("limit_s", limit_s).set("limit_ratio", finest.solve_s / limit_s);
    std::map<std::string, double> rates = table.rates();
    mortar::write_summary(o.out + "/summary.json", parser, rates, results);

    print_comparison(adaptive, uniform.get());
    if (!punch)
      std::printf("effectivity eta / ||u - u_h||: from %.3f to %.3f over every step of both runs (ratio %.3f)\n",
                  eff_lo, eff_hi, eff_hi / eff_lo);
    if (uniform) {
      const double ta = chapter10::time_to_error(adaptive, 0.01), tu = chapter10::time_to_error(*uniform, 0.01);
      if (std::isfinite(ta) && std::isfinite(tu))
        std::printf("to an energy error of 1%%: adaptive %.3f s (%d dofs, every step counted), uniform %.3f s (%d dofs, "
                    "that level alone): %.1f times faster\n",
                    ta, chapter10::dofs_at_error(adaptive, 0.01), tu, chapter10::dofs_at_error(*uniform, 0.01), tu / ta);
      else
        std::printf("to an energy error of 1%%: %s%s not reached (lower --target or --uniform-target, or raise "
                    "--max-dofs)\n", std::isfinite(ta) ? "" : "adaptive ", std::isfinite(tu) ? "" : "uniform");
    }
    std::printf("last solve: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n", finest.dofs, finest.solve_s,
                finest.solve_s / limit_s, limit_s);
    // 6. Figures.
    chapter10::write_figures(o, adaptive, uniform.get(), scene, !o.no_plot);
  } catch (const chapter10::MemoryGuard& e) {
    std::fprintf(stderr, "ch10_adaptive_contact: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch10_adaptive_contact: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
