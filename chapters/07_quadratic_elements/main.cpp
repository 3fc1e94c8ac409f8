// Chapter 7: quadratic elements (q = 2) on both bodies, glued by pointwise or integral matching.
//
// Chapter 4's manufactured two-material scene with P2 triangles (six nodes: vertices and edge
// midpoints) in both bodies. The paper's theorems hold for any degree q:
//   Theorem 4.1 (pointwise matching, V_h^P):  ||u - u_h|| <= C (h1^{1/2} + h2^q),
//   Theorem 4.2 (integral matching, V_h^I):   ||u - u_h|| <= C (h1^q + h2^q),
// so with q = 2 the gap between the two is h^{1/2} against h^2. level.cpp takes the steps of
// one level (P2 stiffness, traces with 2N + 1 nodes, M_h^1 for q = 2, D and M by 3-point Gauss
// on the merged grid, the rows of B, the saddle point); the study around it is chapter 4's,
// with degree 2. Then chapter 4's P1 method on the same scene with the same unknowns
// (p1_comparison.cpp): which degree reaches a given error with fewer unknowns and less time.
//
//   ch07_quadratic_elements                        # integral matching, h2/h1 = 3/2, up to 215k dofs
//   ch07_quadratic_elements --matching pointwise   # Theorem 4.1's h^{1/2}
//   ch07_quadratic_elements --h-ratio 1/3 --no-p1
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "figures.hpp"
#include "middle_half.hpp"
#include "level.hpp"
#include "p1_comparison.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/contact_plots.hpp"

namespace {
struct ChapterOptions {
  mortar::BilateralStudyOptions study;
  std::string matching = "integral";
  bool no_p1 = false;
};

void parse(mortar::OptionParser& parser, ChapterOptions& c, int argc, char** argv) {
  c.study.out = "results/ch07_quadratic_elements";
  c.study.degree = 2;
  c.study.n0 = 6;  // the P2 nodes of n0 = 6 are the P1 nodes of chapter 4's n0 = 12
  parser.add_choice("matching", c.matching, {"pointwise", "integral"},
                    "pointwise (V_h^P: every node of the non-mortar trace, midpoints included) or integral "
                    "(V_h^I: M_h^1 of degree 2)");
  parser.add_flag("no-p1", c.no_p1, "skip chapter 4's P1 study beside it (error at equal unknowns and time)");
  mortar::parse_bilateral_options(parser, c.study, argc, argv);
}

// The slopes the theorems give, each through twice the coarsest value of the series it bounds
// (contact_plots.hpp numbering): an upper bound C h^p drawn there has every finer measurement
// below it when the theorem holds, whatever the constant, and does not hide the curve.
std::vector<mortar::ReferenceSlope> theorem_slopes(mortar::Matching m) {
  if (m == mortar::Matching::pointwise) return {{0.5, 0, -1.0, "slope 1/2: energy bound, Theorem 4.1", "", true}};
  return {{2.0, 0, -1.0, "slope 2: energy bound, Theorem 4.2 (q = 2)", "", true},
          {2.0, 4, -1.0, "slope 2: H^{-1/2} bound (Thm 4.2 + inf-sup), beside H^{-1/2}_h", "", true},
          {1.5, 2, -1.0, "slope 3/2: L^2 bound (inverse inequality)", "", true}};
}
}  // namespace

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  ChapterOptions c;
  mortar::OptionParser parser("ch07_quadratic_elements",
                              "Bilateral frictionless contact of two elastic bodies meshed with P2 triangles on "
                              "nonmatching meshes, glued by pointwise or integral matching, beside P1.");
  parse(parser, c, argc, argv);
  const mortar::BilateralStudyOptions& o = c.study;
  try {
    // 2. Chapter 4's exact two-material solution.
    const mortar::ManufacturedContact exact = mortar::manufactured_solution(o);
    const mortar::Matching matching = mortar::parse_matching(c.matching);
    const bool integral = matching == mortar::Matching::integral;

    // 3. P2 levels, each solved by the steps of level.cpp, then the patch test (h2/h1 = 3/7).
    const mortar::BilateralStudy study =
        mortar::run_bilateral_study(o, exact, {matching, chapter07::solve_quadratic, chapter07::add_middle_half_errors});
    study.table.print_local_rates();

    // 4. P1 on the same scene with the same unknowns.
    mortar::JsonObject extra;
    std::unique_ptr<mortar::BilateralStudy> p1;
    chapter07::EqualError equal{};
    if (!c.no_p1) {
      std::printf("chapter %d's P1 method on the same scene, twice the elements (the same unknowns):\n",
                  integral ? 4 : 3);
      p1 = std::make_unique<mortar::BilateralStudy>(chapter07::run_p1_study(o, exact, matching));
      p1->table.write_csv(o.out + "/p1.csv");
      equal = chapter07::equal_error(study.table, p1->table);
      extra = chapter07::equal_error_results(equal);
    }

    // 5. What the theorems say, next to what we see.
    mortar::write_bilateral_outputs(o, parser, study, extra);
    const auto rates = study.rates();
    const mortar::BilateralLevel& finest = *study.finest;
    std::printf("rates (three finest levels): energy %.3f (%s), L2 %.3f, jump %.3f\n", rates.at("err_energy"),
                integral ? "Theorem 4.2 with q = 2: 2" : "Theorem 4.1 guarantees 1/2: O(h1^{1/2} + h2^2)",
                rates.at("err_l2"), rates.at("err_jump"));
    std::printf("pressure rates: H^{-1/2}_h %.3f (best %.3f), L2 %.3f (best %.3f), interior %.3f (best %.3f)\n",
                rates.at("err_pressure_hminus"), rates.at("err_pressure_best_hminus"), rates.at("err_pressure"),
                rates.at("err_pressure_best"), rates.at("err_pressure_interior"),
                rates.at("err_pressure_best_interior"));
    std::printf("patch test, max |sigma_22 + p| / p at the centroids: integral %.2e, pointwise %.2e\n",
                study.patch_integral.rel_error, study.patch_pointwise.rel_error);
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n", finest.bodies.num_dofs(),
                finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);
    if (p1 && std::isnan(equal.p2_dofs)) {
      // P2's levels all stay above P1's finest error: there is nothing to interpolate
      std::printf("P1's finest energy error %.3e takes P1 %.0f unknowns; P2 does not reach it within the levels run "
                  "(its finest error is %.3e): add levels to compare the cost at equal error\n",
                  equal.error, equal.p1_dofs, study.table.column("err_energy").back());
    } else if (p1) {
      const chapter07::EqualError& e = equal;
      std::printf("P1's finest energy error %.3e takes P1 %.0f unknowns and %.2f units of time; P2 %.0f unknowns "
                  "(%.1f x fewer) and %.3f units (%.1f x less); unit: the finest P1 level's limit\n",
                  e.error, e.p1_dofs, e.p1_time, e.p2_dofs, e.p1_dofs / e.p2_dofs, e.p2_time, e.p1_time / e.p2_time);
    }

    // 6. Figures, the pictures of the problem, the finest level for ParaView.
    const bool run = !o.no_plot;
    const std::string name = c.matching + " matching, P2, " + mortar::mesh_label(o);
    mortar::plot_contact_errors(o.out, study.table, name + ": errors against h", theorem_slopes(matching), run);
    if (p1) chapter07::plot_p2_against_p1(o.out, study.table, p1->table, c.matching, mortar::mesh_label(o), run);
    mortar::plot_pressure(o.out, finest, exact, name + ": contact pressure, finest mesh", run);
    mortar::plot_jump(o.out, finest, name + ": normal jump [u_h.n], finest mesh", run);
    mortar::plot_patch_test(o.out, study.patch_pointwise, study.patch_integral, run);
    mortar::write_bilateral_pictures(o, study);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch07_quadratic_elements: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
