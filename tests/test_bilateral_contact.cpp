// Bilateral contact end to end on small meshes: the patch test and the hard cases of
// docs/hard_cases.md, each giving a finite answer that converges (or a clear error).
#include <gtest/gtest.h>

#include <cmath>

#include "common/study/bilateral_study.hpp"

using namespace mortar;

namespace {
BilateralStudyOptions small(double ratio) {
  BilateralStudyOptions o;
  o.n0 = 6;
  o.h_ratio = ratio;
  return o;
}

// Energy errors of two consecutive levels (n0 and 2 n0) and the observed rate between them.
struct TwoLevels {
  double coarse, fine, rate;
};
TwoLevels two_levels(const BilateralStudyOptions& o, Matching m, int first_level = 0) {
  const ManufacturedContact exact(Material(o.E1, o.nu1), Material(o.E2, o.nu2), o.L);
  const BilateralOptions s = solver_options(o, m);
  const BilateralLevel a = solve_manufactured_level(exact, level_geometry(o, first_level), s);
  const BilateralLevel b = solve_manufactured_level(exact, level_geometry(o, first_level + 1), s);
  return {a.err_energy, b.err_energy, std::log(a.err_energy / b.err_energy) / std::log(std::max(a.h1, a.h2) / std::max(b.h1, b.h2))};
}
}  // namespace

TEST(BilateralContact, integral_matching_passes_the_patch_test_pointwise_does_not) {
  for (double jitter : {0.0, 0.3})
    for (int nonmortar : {1, 2}) {
      BilateralStudyOptions o = small(1.5);
      o.jitter = jitter;
      o.nonmortar = nonmortar;
      o.E2 = 7;
      EXPECT_LT(run_patch_test(o, Matching::integral).rel_error, 1e-10) << "jitter " << jitter << ", nm " << nonmortar;
      EXPECT_GT(run_patch_test(o, Matching::pointwise).rel_error, 1e-4) << "jitter " << jitter << ", nm " << nonmortar;
    }
}

// Hard case rows (docs/hard_cases.md). A "converging answer": finite errors, the finer level better,
// and for integral matching an observed energy rate near Theorem 4.2's 1 (band 0.75: these
// are levels 6-12 and 12-24 elements, still pre-asymptotic for the extreme cases).

TEST(BilateralContact, mesh_ratios_from_1_10_to_10_converge) {
  for (double ratio : {0.1, 1.0 / 3, 2.0 / 3, 1.5, 3.0, 10.0})
    for (Matching m : {Matching::pointwise, Matching::integral}) {
      const TwoLevels t = two_levels(small(ratio), m, 1);
      EXPECT_TRUE(std::isfinite(t.fine)) << "ratio " << ratio;
      EXPECT_LT(t.fine, t.coarse) << "ratio " << ratio << ", " << matching_name(m);
      if (m == Matching::integral) {
        EXPECT_GT(t.rate, 0.75) << "ratio " << ratio;
      }
    }
}

TEST(BilateralContact, stiffness_ratios_from_1e_minus6_to_1e6_converge) {
  for (double E2 : {1e-6, 1e-3, 1.0, 1e3, 1e6})
    for (const char* solver : {"elimination", "lu"}) {
      BilateralStudyOptions o = small(1.5);
      o.E2 = E2;
      o.saddle_solver = solver;
      for (Matching m : {Matching::pointwise, Matching::integral}) {
        const TwoLevels t = two_levels(o, m, 1);
        EXPECT_TRUE(std::isfinite(t.fine)) << "E1/E2 = " << 1 / E2 << ", " << solver;
        EXPECT_LT(t.fine, t.coarse) << "E1/E2 = " << 1 / E2 << ", " << matching_name(m) << ", " << solver;
        if (m == Matching::integral) {
          EXPECT_GT(t.rate, 0.75) << "E1/E2 = " << 1 / E2;
        }
      }
    }
}

TEST(BilateralContact, traces_1e14_apart_give_the_matching_answer) {
  BilateralStudyOptions o = small(1.0);
  const ManufacturedContact exact(Material(o.E1, o.nu1), Material(o.E2, o.nu2), o.L);
  const TwoBodyGeometry g = level_geometry(o, 1);
  const TwoBodies matching = make_two_bodies(g, exact.material(0), exact.material(1));
  // the same meshes, with body 2's nodes on Gamma_c moved by +-1e-14
  Mesh shifted = matching.body(1).mesh;
  const auto& top = shifted.nodes_on(Side::top);
  for (std::size_t i = 1; i + 1 < top.size(); ++i) shifted.nodes[top[i]].x() += (i % 2 ? 1e-14 : -1e-14);
  const TwoBodies near(matching.body(0), {shifted, exact.material(1)});
  for (Matching m : {Matching::pointwise, Matching::integral}) {
    const BilateralOptions s = solver_options(o, m);
    const BilateralSolution a = solve_bilateral(matching, manufactured_scene(matching, exact), s);
    const BilateralSolution b = solve_bilateral(near, manufactured_scene(near, exact), s);
    ASSERT_EQ(a.lambda.size(), b.lambda.size());
    EXPECT_LT((a.u - b.u).norm(), 1e-10 * a.u.norm()) << matching_name(m);
    EXPECT_LT((a.lambda - b.lambda).norm(), 1e-8 * a.lambda.norm()) << matching_name(m);
  }
}

TEST(BilateralContact, jittered_and_anisotropic_meshes_converge) {
  for (auto [jitter, aspect] : {std::pair{0.3, 1.0}, {0.0, 20.0}, {0.3, 20.0}, {0.0, 0.05}}) {
    BilateralStudyOptions o = small(1.5);
    o.jitter = jitter;
    o.aspect = aspect;
    o.n0 = aspect > 1 ? 4 : 12;
    for (Matching m : {Matching::pointwise, Matching::integral}) {
      const TwoLevels t = two_levels(o, m);
      EXPECT_TRUE(std::isfinite(t.fine));
      EXPECT_LT(t.fine, t.coarse) << "jitter " << jitter << ", aspect " << aspect << ", " << matching_name(m);
    }
  }
}

TEST(BilateralContact, nearly_incompressible_bodies_give_a_finite_answer_that_locks) {
  // P1 locks as nu -> 1/2: the answer stays finite and converges, but slowly; we show it.
  BilateralStudyOptions o = small(1.5);
  o.nu1 = o.nu2 = 0.4999;
  const TwoLevels t = two_levels(o, Matching::integral, 1);
  EXPECT_TRUE(std::isfinite(t.fine));
  EXPECT_LT(t.fine, t.coarse);
}

// lambda_h is in M_h^1, so its L2 error can never be below the best approximation of -sigma_N
// there; the row's relative columns split the same way as the absolute norms.
TEST(BilateralContact, integral_pressure_is_never_better_than_its_best_approximation) {
  for (double ratio : {1.0 / 3, 1.5, 3.0})
    for (int nonmortar : {1, 2}) {
      BilateralStudyOptions o = small(ratio);
      o.nonmortar = nonmortar;
      const BilateralLevel level = solve_manufactured_level(manufactured_solution(o), level_geometry(o, 1),
                                                            solver_options(o, Matching::integral));
      const PressureErrors& p = level.pressure_errors;
      EXPECT_GE(p.l2, p.best_l2) << "ratio " << ratio << ", nm " << nonmortar;
      EXPECT_NEAR(p.l2 * p.l2, p.l2_interior * p.l2_interior + p.l2_ends * p.l2_ends, 1e-12 * p.l2 * p.l2);
      double interior = 0, ends = 0, whole = 0;
      for (const auto& [column, value] : level.row()) {
        if (column == "err_pressure") whole = value;
        if (column == "err_pressure_interior") interior = value;
        if (column == "err_pressure_ends") ends = value;
      }
      EXPECT_NEAR(whole, p.l2 / p.norm_l2, 1e-15);
      EXPECT_NEAR(whole * whole, interior * interior + ends * ends, 1e-12 * whole * whole);
    }
}

TEST(BilateralContact, flat_pressure_ends_give_a_pressure_without_slope_at_both_ends) {
  BilateralStudyOptions o = small(1.5);
  const auto slope = [&](const ManufacturedContact& exact, double x) {
    const double d = 1e-6 * o.L;
    return (exact.pressure(x + d) - exact.pressure(x - d)) / (2 * d);
  };
  const ManufacturedContact sloped = manufactured_solution(o);
  EXPECT_GT(std::fabs(slope(sloped, o.L)), 1e-3);
  o.pressure_ends = "flat";
  const ManufacturedContact flat = manufactured_solution(o);
  EXPECT_LT(std::fabs(slope(flat, 0.0)), 1e-8);
  EXPECT_LT(std::fabs(slope(flat, o.L)), 1e-8);
  EXPECT_GT(flat.pressure(0.5 * o.L), 0.0);  // still pressed everywhere: bilateral is the right model
}
