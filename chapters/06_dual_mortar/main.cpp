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
#include <cstdio>
#include <exception>

#include "bilateral_level.hpp"
#include "common/interface/dual_basis.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  mortar::BilateralStudyOptions o;
  o.out = "results/ch06_dual_mortar";
  bool no_compare = false;
  mortar::OptionParser parser("ch06_dual_mortar",
                              "Dual (biorthogonal) mortar multipliers: condensation of the bilateral problem, "
                              "and the semismooth Newton method for unilateral contact.");
  parser.add_flag("no-compare", no_compare, "skip the standard mortar basis (chapter 4) on the same levels");
  mortar::parse_bilateral_options(parser, o, argc, argv);
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
    mortar::write_bilateral_outputs(o, parser, dual, extra);
    const auto rates = dual.rates();
    std::printf("dual basis: rates (three finest levels): energy %.3f (Theorem 4.2 with M_h dual: 1), L2 %.3f, "
                "pressure L2 %.3f, H^{-1/2}_h %.3f\n",
                rates.at("err_energy"), rates.at("err_l2"), rates.at("err_pressure"), rates.at("err_pressure_hminus"));
    std::printf("D off its diagonal: max |D_ij| / D_ii = %.2e; patch test max |sigma_22 + p| / p = %.2e\n", offdiagonal,
                dual.patch_integral.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n", finest.bodies.num_dofs(),
                finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch06_dual_mortar: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
