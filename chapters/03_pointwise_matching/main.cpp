// Chapter 3: pointwise matching of two bodies with nonmatching meshes.
//
// Two elastic bodies of different materials meet on Gamma_c; their meshes do not match there.
// The simplest glue is the paper's space V_h^P: the normal displacements agree at the nodes
// xi^1 of the non-mortar side,
//   u1(a).n1 + u2(a).n2 = 0  for every node a of xi^1,
// one row of B per node. level.cpp takes the steps of one level in the order of the lecture
// (K, the traces, the pointwise rows of B, Dirichlet elimination, the saddle point (8), the
// pressure and the jump); the study around it is common/study/bilateral_study.cpp. The program
// measures the broken energy and L2 errors of u and the L2(Gamma_c) errors of the pressure and
// of the jump, beside Theorem 4.1 (O(h1^{1/2} + h2) in the energy norm), and runs the patch
// test, which pointwise matching fails. Figures: the errors, the pressure, the jump, the patch
// test, the coarsest meshes with the nodes xi^1 (meshes.png) and deformed (deformed.png);
// body1.vtu, body2.vtu and contact.vtu hold the finest level for ParaView.
//
//   ch03_pointwise_matching                      # h2/h1 = 3/2, up to about 215k dofs
//   ch03_pointwise_matching --h-ratio 1/3        # the non-mortar side is the coarse one
//   ch03_pointwise_matching --nonmortar 2
#include <cmath>
#include <cstdio>
#include <exception>

#include "level.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  mortar::BilateralStudyOptions o;
  o.out = "results/ch03_pointwise_matching";
  mortar::OptionParser parser("ch03_pointwise_matching",
                              "Bilateral frictionless contact of two elastic bodies on nonmatching "
                              "meshes, glued at the nodes of the non-mortar side.");
  mortar::parse_bilateral_options(parser, o, argc, argv);
  try {
    // 2. The exact two-material solution: the bodies slide on each other, stay glued in y.
    const mortar::ManufacturedContact exact = mortar::manufactured_solution(o);

    // 3. Refine both meshes together with h2/h1 fixed, each level solved by the steps of
    //    level.cpp, then the patch test (h2/h1 = 3/7).
    const mortar::BilateralStudy study =
        mortar::run_bilateral_study(o, exact, {mortar::Matching::pointwise, chapter03::solve_pointwise_matching, {}});

    // 4. What Theorem 4.1 says, next to what we see.
    mortar::write_bilateral_outputs(o, parser, study);
    const auto rates = study.rates();
    const mortar::BilateralLevel& finest = *study.finest;
    std::printf("rates (three finest levels): energy %.3f (Theorem 4.1 guarantees 1/2: "
                "O(h1^{1/2} + h2)), L2 %.3f, pressure %.3f, jump %.3f\n",
                rates.at("err_energy"), rates.at("err_l2"), rates.at("err_pressure"), rates.at("err_jump"));
    if (std::isnan(rates.at("err_jump")))
      std::printf("the jump [u_h.n] is identically zero at every level: every node of the mortar "
                  "trace is a node of the non-mortar trace (nested grids), so V_h^P is conforming\n");
    std::printf("patch test, max |sigma_22 + p| / p: pointwise %.2e, integral %.2e\n",
                study.patch_pointwise.rel_error, study.patch_integral.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n",
                finest.bodies.num_dofs(), finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);

    // 5. Figures.
    const bool run = !o.no_plot;
    const std::string name = "pointwise matching, " + mortar::mesh_label(o);
    mortar::plot_contact_errors(o.out, study.table, name + ": errors against h",
                                {{0.5, 0, 0.4, "slope 1/2 (Theorem 4.1: h1^{1/2} + h2)", ""},
                                 {1.0, 0, 0.7, "slope 1 (what integral matching reaches, for comparison)", ""}}, run);
    mortar::plot_contact_error_vs_time(o.out, study.table, name + ": error against wall time", run);
    mortar::plot_pressure(o.out, finest, exact,
                          name + ": nodal force / tributary length, finest mesh", run);
    mortar::plot_jump(o.out, finest, name + ": normal jump [u_h.n], finest mesh", run);
    mortar::plot_patch_test(o.out, study.patch_pointwise, study.patch_integral, run);
    // 6. Pictures of the problem, and the finest level for ParaView.
    mortar::write_bilateral_pictures(o, study);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch03_pointwise_matching: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
