// Chapter 7: quadratic (P2) elements on both bodies, glued by pointwise or integral matching.
#include <cmath>
#include <cstdio>
#include <exception>

#include "level.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

int main(int argc, char** argv) {
  mortar::BilateralStudyOptions o;
  o.out = "results/ch07_quadratic_elements";
  o.n0 = 6;
  o.degree = 2;
  std::string matching = "integral";
  mortar::OptionParser parser("ch07_quadratic_elements",
                              "Bilateral frictionless contact of two elastic bodies meshed with P2 triangles "
                              "on nonmatching meshes, glued by pointwise or integral matching.");
  parser.add_choice("matching", matching, {"pointwise", "integral"},
                    "pointwise (V_h^P: every node of the non-mortar trace) or integral (V_h^I: M_h^1 of degree 2)");
  mortar::parse_bilateral_options(parser, o, argc, argv);
  try {
    const mortar::ManufacturedContact exact = mortar::manufactured_solution(o);
    const mortar::Matching m = mortar::parse_matching(matching);
    const mortar::BilateralStudy study = mortar::run_bilateral_study(o, exact, {m, chapter07::solve_quadratic, {}});
    mortar::write_bilateral_outputs(o, parser, study);
    const auto rates = study.rates();
    const mortar::BilateralLevel& finest = *study.finest;
    std::printf("rates: energy %.3f, L2 %.3f, pressure %.3f, hminus %.3f, jump %.3f\n", rates.at("err_energy"),
                rates.at("err_l2"), rates.at("err_pressure"), rates.at("err_pressure_hminus"), rates.at("err_jump"));
    std::printf("patch test: integral %.2e, pointwise %.2e\n", study.patch_integral.rel_error,
                study.patch_pointwise.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the limit\n", finest.bodies.num_dofs(), finest.time_s,
                finest.time_s / finest.limit_s);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch07_quadratic_elements: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
