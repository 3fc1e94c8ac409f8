// Chapter 6: dual (biorthogonal) multipliers. D becomes diagonal, the constraints are solved
// node by node for the non-mortar normal dofs, and the multipliers leave the linear algebra.
//
// Part 1 (bilateral): chapter 4's two-material manufactured solution and patch test, with the
// dual basis in place of the hats of M_h^1 (bilateral_level.cpp: the steps in the order of the
// lecture). The non-mortar normal dofs are condensed, u_s = -(B_r u) / b, one Cholesky of
// T^T K T; the multipliers are read node by node. Beside it, on the same levels, chapter 4's
// standard mortar (the saddle point through S = B K^{-1} B^T): errors, rates, time.
// Part 2 (unilateral): chapter 5's Hertz scene, the weighted gap of the dual basis and the
// semismooth Newton method in the displacements, beside chapter 5's primal-dual active set
// with the standard basis: iterations, total force, time against the limit (hertz_study.cpp).
// Figures: the dual basis beside the hats, errors against h and against time for both bases,
// the pressure of both, and the Hertz pressures.
//
//   ch06_dual_mortar                        # h2/h1 = 3/2, up to about 215k dofs, then Hertz
//   ch06_dual_mortar --h-ratio 1/3 --nonmortar 2
//   ch06_dual_mortar --no-compare --no-hertz
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>

#include "bilateral_level.hpp"
#include "figures.hpp"
#include "hertz_study.hpp"
#include "partial_coverage.hpp"
#include "common/study/two_body_pictures.hpp"
#include "common/interface/dual_basis.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

namespace {
// Both bases level by level: dofs, the energy error, the pressure error, time and its ratio.
void print_comparison(const mortar::ConvergenceTable& dual, const mortar::ConvergenceTable& standard) {
  const auto dofs = dual.column("dofs"), ed = dual.column("err_energy"), es = standard.column("err_energy");
  const auto pd = dual.column("err_pressure_function"), pn = dual.column("err_pressure"), ps = standard.column("err_pressure");
  const auto td = dual.column("time_s"), ts = standard.column("time_s"), ld = dual.column("limit_s"),
             ls = standard.column("limit_s");
  std::printf("%9s | %-21s | %-32s | %-23s\n", "", "energy error", "pressure L2 error", "time / limit");
  std::printf("%9s | %10s %10s | %10s %10s %10s | %11s %11s\n", "dofs", "standard", "dual", "standard", "dual fn",
              "dual nodes", "standard", "dual");
  for (std::size_t k = 0; k < dofs.size(); ++k)
    std::printf("%9.0f | %10.4e %10.4e | %10.4e %10.4e %10.4e | %11.2f %11.2f\n", dofs[k], es[k], ed[k], ps[k], pd[k],
                pn[k], ts[k] / ls[k], td[k] / ld[k]);
}
}  // namespace

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  mortar::BilateralStudyOptions o;
  o.out = "results/ch06_dual_mortar";
  bool no_compare = false, no_hertz = false;
  chapter06::HertzOptions hertz;
  mortar::OptionParser parser("ch06_dual_mortar",
                              "Dual (biorthogonal) mortar multipliers: condensation of the bilateral problem, "
                              "and the semismooth Newton method for unilateral contact.");
  parser.add_flag("no-compare", no_compare, "skip the standard mortar basis (chapter 4) on the same levels");
  parser.add_flag("no-hertz", no_hertz,
                  "skip part 2, unilateral contact on chapter 5's Hertz scene (same --n0, --levels, --h-ratio)");
  std::string hertz_start = "nested";
  parser.add_choice("hertz-start", hertz_start, {"nested", "empty"},
                    "the dual Newton method's first active set: from the level below, or none");
  mortar::parse_bilateral_options(parser, o, argc, argv, [&no_hertz](const mortar::BilateralStudyOptions& b) {
    return no_hertz ? std::vector<mortar::MemoryPart>{} : chapter06::hertz_memory_parts(b);
  });
  // a body much stiffer than the other makes a poor non-mortar side: the Hertz part's
  // semismooth Newton cycles with it at E1/E2 = 1e6 (chapter 5's evidence, "Hard cases")
  mortar::choose_softer_nonmortar(parser, o);
  // Part 2 runs on chapter 5's bodies (square blocks of one material) unless materials are
  // given, with the same sizes along Gamma_c as part 1. Its lengths follow --L: blocks L tall,
  // R = L, delta = 0.02 L, so that its strains and pressures do not depend on the unit.
  hertz.bodies = o;
  hertz.bodies.H1 = hertz.bodies.H2 = o.L;
  hertz.R = o.L;
  hertz.delta = 0.02 * o.L;
  if (!parser.given("E2")) hertz.bodies.E2 = 1;
  if (!parser.given("nu2")) hertz.bodies.nu2 = 0.3;
  hertz.nested_start = hertz_start == "nested";
  hertz.n0 = o.n0;
  hertz.levels = o.levels;
  try {
    // 2. Chapter 4's exact solution: two materials glued in y, sliding in x.
    const mortar::ManufacturedContact exact = mortar::manufactured_solution(o);

    // 3. The dual basis on every level (and in the patch test), solved by condensation; the
    //    multiplier is measured twice: its coefficients read as nodal values (chapter 4's
    //    curve, err_pressure) and the function sum lambda_i psi_i itself (err_pressure_function).
    const mortar::BilateralStudy dual = mortar::run_bilateral_study(
        o, exact, {mortar::Matching::integral, chapter06::solve_dual_mortar, chapter06::add_function_error});
    const mortar::BilateralLevel& finest = *dual.finest;
    const double offdiagonal = mortar::d_offdiagonal_max(finest.solution.gamma.space, finest.solution.gamma.matrices.D);

    mortar::JsonObject extra;
    extra.set("basis", "dual").set("d_offdiagonal_max", offdiagonal);
    // 4. Part 2: Hertz with both bases, the same meshes, each level timed against its limit.
    std::unique_ptr<chapter06::HertzStudy> hertz_study;
    if (!no_hertz) {
      hertz_study = std::make_unique<chapter06::HertzStudy>(chapter06::run_hertz_study(hertz));
      const chapter06::HertzStudy& h = *hertz_study;
      chapter06::write_hertz_csv(o.out + "/hertz.csv", h);
      const chapter06::HertzLevel &s = h.standard.back(), &d = h.dual.back();
      extra.set("hertz_dofs", s.dofs)
          .set("hertz_total_force_standard", s.total_force)
          .set("hertz_total_force_dual", d.total_force)
          .set("hertz_total_force_rel_difference", std::fabs(d.total_force - s.total_force) / std::fabs(s.total_force))
          .set("hertz_iterations_standard", s.iterations)
          .set("hertz_iterations_dual", d.iterations)
          .set("hertz_limit_ratio_standard", s.timing.ratio())
          .set("hertz_limit_ratio_dual", d.timing.ratio())
          .set("hertz_min_function_dual", d.min_function)
          .set("hertz_pressure_rel_difference", d.pressure_difference)
          .set("hertz_complementarity_residual_dual", d.residual);
      std::printf("Hertz, finest level (%d dofs): total force standard %.8g, dual %.8g (relative difference %.2e); "
                  "iterations %d (active set on S) and %d (Newton, one factorization each); time %.2f and %.2f x "
                  "the limit\n",
                  s.dofs, s.total_force, d.total_force, std::fabs(d.total_force - s.total_force) / s.total_force,
                  s.iterations, d.iterations, s.timing.ratio(), d.timing.ratio());
      mortar::print_active_sets(s.active_sets);
      mortar::print_active_sets(d.active_sets);
    }
    mortar::write_bilateral_outputs(o, parser, dual, extra);
    const auto rates = dual.rates();
    std::printf("dual basis: rates (three finest levels): energy %.3f (Theorem 4.2 with M_h dual: 1), L2 %.3f, "
                "pressure L2 %.3f, H^{-1/2}_h %.3f\n",
                rates.at("err_energy"), rates.at("err_l2"), rates.at("err_pressure"), rates.at("err_pressure_hminus"));
    std::printf("dual basis, ");
    dual.table.print_local_rates();
    std::printf("D off its diagonal: max |D_ij| / D_ii = %.2e; patch test max |sigma_22 + p| / p = %.2e\n", offdiagonal,
                dual.patch_integral.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n", finest.bodies.num_dofs(),
                finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);
    // 5. The hard case of dual bases that the scenes above cannot have: a non-mortar element
    //    covered in part by the mortar side (1D traces, 24 non-mortar elements).
    const auto partial = chapter06::partial_coverage(24, {1.0, 0.75, 0.5, 0.25, 0.1});
    chapter06::write_partial_coverage_csv(o.out + "/partial_coverage.csv", partial);
    std::printf("partly covered element (mortar side ends at theta h inside it):\n%8s %14s %20s %18s %22s\n",
                "theta", "max|D_ij|/D_ii", "min D_ii/int phi_i", "|w1 - 1|, D whole", "|w1 - 1|, D diagonal");
    for (const auto& c : partial)
      std::printf("%8.2f %14.3e %20.3f %18.3e %22.3e\n", c.covered, c.offdiagonal, c.diagonal_ratio_min,
                  c.constant_error_full, c.constant_error_diagonal);

    // 6. Chapter 4's standard basis on the same levels, for the comparison (standard.csv).
    std::unique_ptr<mortar::BilateralStudy> standard;
    if (!no_compare) {
      std::printf("the standard basis of M_h^1 (chapter 4), same levels:\n");
      standard = std::make_unique<mortar::BilateralStudy>(
          mortar::run_bilateral_study(o, exact, {mortar::Matching::integral, mortar::solve_bilateral, {}}));
      standard->table.write_csv(o.out + "/standard.csv");
      standard->table.local_rates().write_csv(o.out + "/standard_local_rates.csv", true);
      std::printf("standard basis, ");
      standard->table.print_local_rates();
      print_comparison(dual.table, standard->table);
    }

    // 7. Figures.
    const bool run = !o.no_plot;
    const std::string mesh = mortar::mesh_label(o);
    chapter06::plot_dual_basis(o.out, run);
    const mortar::ConvergenceTable* standard_table = standard ? &standard->table : nullptr;
    chapter06::plot_bases_against_h(o.out, dual.table, standard_table, mesh, run);
    chapter06::plot_bases_against_time(o.out, dual.table, standard_table, mesh, run);
    chapter06::plot_dual_pressure(o.out, *dual.coarsest, exact, mesh, run);
    mortar::plot_pressure(o.out, finest, exact, "dual multipliers, " + mesh + ": the coefficients lambda_i at their nodes, finest mesh", run);
    mortar::plot_jump(o.out, finest, "dual multipliers, " + mesh + ": normal jump [u_h.n], finest mesh", run);
    mortar::plot_patch_test(o.out, dual.patch_pointwise, dual.patch_integral, run, "integral matching, dual basis");
    // the finest level for ParaView: both bodies deformed, the dual coefficients and the jump on Gamma_c
    mortar::write_two_body_vtu(o.out, finest.bodies, finest.solution.u, finest.pressure, finest.jump);
    if (hertz_study) {
      chapter06::plot_hertz_pressure(o.out, *hertz_study, hertz, run);
      const chapter06::HertzLevel &s = hertz_study->standard.back(), &d = hertz_study->dual.back();
      char title[160];
      std::snprintf(title, sizeof title, "Hertz, finest level (%d dofs, h_2/h_1 = %.3g): the active set, step by step",
                    d.dofs, o.h_ratio);
      mortar::write_active_sets(o.out, title, {s.active_sets, d.active_sets}, run);
    }
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch06_dual_mortar: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
