// Chapter 4: integral (mortar) matching of two bodies with nonmatching meshes.
//
// The same two bodies as chapter 3, glued in the weak sense of the paper's space V_h^I:
//   int_{Gamma_c} [u_h.n] psi = 0  for every psi in M_h^1,
// one row  sum_j D_ij u1_j.n1 + sum_k M_ik u2_k.n2 = 0  per multiplier. level.cpp takes the
// steps of one level in the order of the lecture (K, the traces, the merged grid, M_h^1, D and
// M, the rows of B, Dirichlet elimination, the saddle point (8), the pressure and the jump);
// the study around it (common/study/bilateral_study.cpp) is chapter 3's. The program measures
// the broken energy and L2 errors of u against Theorem 4.2 (O(h)); the contact pressure
// lambda_h in L2(Gamma_c) and in the mesh-dependent H^{-1/2} norm, each beside the L2 best
// approximation of -sigma_N in M_h^1, with the end elements split off; the jump [u_h.n]. Then
// the patch test, which integral matching passes to round-off and pointwise matching fails.
// Figures: the errors, the pressure, the jump, the patch test, the coarsest meshes with their
// traces and merged grid (meshes.png) and deformed (deformed.png); body1.vtu, body2.vtu and
// contact.vtu hold the finest level for ParaView.
//
//   ch04_integral_matching                       # h2/h1 = 3/2, up to about 215k dofs
//   ch04_integral_matching --pressure-ends flat  # sigma_N' = 0 at both ends of Gamma_c
//   ch04_integral_matching --h-ratio 1/3 --nonmortar 2
//   ch04_integral_matching --E1 1e6 --E2 1 --jitter 0.3
#include <cstdio>
#include <exception>

#include "level.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  mortar::BilateralStudyOptions o;
  o.out = "results/ch04_integral_matching";
  mortar::OptionParser parser("ch04_integral_matching",
                              "Bilateral frictionless contact of two elastic bodies on nonmatching "
                              "meshes, glued by integral (mortar) matching.");
  mortar::parse_bilateral_options(parser, o, argc, argv);
  try {
    // 2. The exact two-material solution: the bodies slide on each other, stay glued in y;
    //    --pressure-ends picks sigma_N' != 0 (sloped) or = 0 (flat) at the ends of Gamma_c.
    const mortar::ManufacturedContact exact = mortar::manufactured_solution(o);

    // 3. Refine both meshes together with h2/h1 fixed, each level solved by the steps of
    //    level.cpp, then the patch test (h2/h1 = 3/7).
    const mortar::BilateralStudy study =
        mortar::run_bilateral_study(o, exact, {mortar::Matching::integral, chapter04::solve_integral_matching, {}});

    // 4. What theory says, next to what we see.
    mortar::write_bilateral_outputs(o, parser, study);
    const auto rates = study.rates();
    const mortar::BilateralLevel& finest = *study.finest;
    std::printf("rates (three finest levels): energy %.3f (Theorem 4.2: 1), L2 %.3f, jump %.3f\n",
                rates.at("err_energy"), rates.at("err_l2"), rates.at("err_jump"));
    std::printf("pressure rates: H^{-1/2}_h %.3f (Theorem 4.2 with inf-sup: 1; best %.3f), "
                "L2 %.3f (guaranteed: 1/2; best %.3f), interior %.3f (best %.3f)\n",
                rates.at("err_pressure_hminus"), rates.at("err_pressure_best_hminus"), rates.at("err_pressure"),
                rates.at("err_pressure_best"), rates.at("err_pressure_interior"),
                rates.at("err_pressure_best_interior"));
    std::printf("finest level, pressure L2 error / best approximation: %.2f (interior %.2f)\n",
                finest.pressure_errors.l2 / finest.pressure_errors.best_l2,
                finest.pressure_errors.l2_interior / finest.pressure_errors.best_l2_interior);
    std::printf("patch test, max |sigma_22 + p| / p: integral %.2e, pointwise %.2e\n",
                study.patch_integral.rel_error, study.patch_pointwise.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n",
                finest.bodies.num_dofs(), finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);

    // 5. Figures.
    const bool run = !o.no_plot;
    const std::string name = "integral matching, " + mortar::mesh_label(o);
    //    Reference slopes only beside what a theorem bounds: the energy and the pressure in
    //    H^{-1/2} (Theorem 4.2, with the inf-sup condition for lambda_h), and the pressure in
    //    L2, where the inverse inequality leaves h^{1/2}.
    mortar::plot_contact_errors(o.out, study.table, name + ": errors against h",
                                {{1.0, 0, 0.4, "slope 1: energy, Theorem 4.2", ""},
                                 {1.0, 4, 0.4, "slope 1: pressure in H^{-1/2}, Theorem 4.2 + inf-sup", ""},
                                 {0.5, 2, 0.4, "slope 1/2: pressure in L^2, guaranteed", ""}},
                                run);
    mortar::plot_contact_error_vs_time(o.out, study.table, name + ": error against wall time", run);
    mortar::plot_pressure(o.out, finest, exact, name + ": contact pressure lambda_h, finest mesh", run);
    mortar::plot_jump(o.out, finest, name + ": normal jump [u_h.n], finest mesh", run);
    mortar::plot_patch_test(o.out, study.patch_pointwise, study.patch_integral, run);
    // 6. Pictures of the problem, and the finest level for ParaView.
    mortar::write_bilateral_pictures(o, study);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch04_integral_matching: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
