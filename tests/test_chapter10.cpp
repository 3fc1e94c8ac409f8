// Chapter 10's own pieces, built from the chapter's sources: Doerfler's marking (hand-worked
// cases and, on a random vector, the smallest set carrying the share, by brute force), the
// singular exponent of a wedge on a half-plane (its limits, and values derived independently),
// Gamma_c of the punch cut to where both bodies have it (ends, the patch test's row sums, an end
// that is not a node), the nested start against a cold one (same answers, no more Newton steps),
// and on the exact Hertz scene the effectivity band and the adaptive rate in N.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "adaptive_loop.hpp"
#include "contact_step.hpp"
#include "marking.hpp"
#include "scenes.hpp"
#include "study.hpp"
#include "wedge_exponent.hpp"

using chapter10::doerfler_marking;

namespace {

std::vector<int> marked_indices(const std::vector<bool>& marked) {
  std::vector<int> k;
  for (std::size_t i = 0; i < marked.size(); ++i)
    if (marked[i]) k.push_back(static_cast<int>(i));
  return k;
}

const double pi = std::acos(-1.0);

}  // namespace

// ---------------------------------------------------------------------------------------------
// MARK: Doerfler's bulk criterion

// eta2 = {4, 1, 3, 2}, total 10: theta = 0.5 needs 5, the largest two (4 + 3 = 7) are the first
// to reach it; 0.4 is reached by the largest alone; 0.75 needs 4 + 3 + 2 = 9.
TEST(DoerflerMarking, hand_worked_shares) {
  const std::vector<double> eta2 = {4, 1, 3, 2};
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.5)), (std::vector<int>{0, 2}));
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.4)), (std::vector<int>{0}));
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.7)), (std::vector<int>{0, 2}));
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.75)), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.95)), (std::vector<int>{0, 1, 2, 3}));
}

// theta = 1 marks every triangle whose indicator is not zero (and no zero one); theta = 0 only
// the largest, so that the loop keeps refining.
TEST(DoerflerMarking, theta_one_marks_every_nonzero_and_theta_zero_the_largest) {
  const std::vector<double> eta2 = {0.5, 0, 2, 0.25, 0, 7};
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 1.0)), (std::vector<int>{0, 2, 3, 5}));
  EXPECT_EQ(marked_indices(doerfler_marking(eta2, 0.0)), (std::vector<int>{5}));
  EXPECT_EQ(marked_indices(doerfler_marking({4, 1, 3, 2}, 1.0)), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(marked_indices(doerfler_marking({4, 1, 3, 2}, 0.0)), (std::vector<int>{0}));
}

// theta = 1 is uniform refinement of every triangle with an error: also those whose indicators
// vanish in the round-off of the sum (1 + 1e-17 == 1), which the running sum cannot tell from
// having reached the whole.
TEST(DoerflerMarking, theta_one_marks_indicators_below_the_round_off_of_the_total) {
  EXPECT_EQ(marked_indices(doerfler_marking({1, 1e-17}, 1.0)), (std::vector<int>{0, 1}));
  EXPECT_EQ(marked_indices(doerfler_marking({0.5, 0, 2, 1e-300, 0, 7}, 1.0)), (std::vector<int>{0, 2, 3, 5}));
}

// Equal indicators: the first in index order goes first, so a run is reproducible; the share
// still decides how many.
TEST(DoerflerMarking, ties_are_taken_in_index_order) {
  EXPECT_EQ(marked_indices(doerfler_marking({1, 1, 1, 1}, 0.5)), (std::vector<int>{0, 1}));
  EXPECT_EQ(marked_indices(doerfler_marking({1, 1, 1, 1}, 0.0)), (std::vector<int>{0}));
  EXPECT_EQ(marked_indices(doerfler_marking({2, 3, 1, 3}, 0.5)), (std::vector<int>{1, 3}));
  EXPECT_EQ(marked_indices(doerfler_marking({2, 3, 1, 3}, 0.3)), (std::vector<int>{1}));
}

// All indicators zero (the exact solution in the discrete space): whatever theta, one triangle
// at most, and the result has the input's size; an empty input gives an empty result.
TEST(DoerflerMarking, all_zero_and_empty_indicators) {
  for (double theta : {0.0, 0.5, 1.0}) {
    const std::vector<bool> m = doerfler_marking(std::vector<double>(5, 0.0), theta);
    ASSERT_EQ(m.size(), 5u);
    EXPECT_LE(std::count(m.begin(), m.end(), true), 1) << "theta = " << theta;
    EXPECT_TRUE(doerfler_marking({}, theta).empty());
  }
}

TEST(DoerflerMarking, theta_outside_zero_one_throws) {
  const std::vector<double> eta2 = {4, 1, 3, 2};
  const double inf = std::numeric_limits<double>::infinity();
  for (double theta : {-0.1, 1.5, 1.0000001, std::nan(""), inf, -inf})
    EXPECT_THROW(doerfler_marking(eta2, theta), std::invalid_argument) << "theta = " << theta;
}

// The marked set is a smallest one carrying the share: over all 1024 subsets of a random
// 10-vector, none with the share is smaller, and the marked set has the share (for every theta
// of a fine scan, and the largest indicators are the ones taken).
TEST(DoerflerMarking, the_marked_set_is_the_smallest_with_the_share) {
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> eta2(10);
    for (double& v : eta2) v = u(rng) * u(rng);  // spread out, no ties
    const double total = std::accumulate(eta2.begin(), eta2.end(), 0.0);
    for (int t = 1; t <= 100; ++t) {
      const double theta = t / 100.0;
      const std::vector<bool> marked = doerfler_marking(eta2, theta);
      double share = 0;
      for (int i = 0; i < 10; ++i) share += marked[i] ? eta2[i] : 0;
      const long count = std::count(marked.begin(), marked.end(), true);
      EXPECT_GE(share, theta * total * (1 - 1e-14)) << "theta = " << theta;
      int smallest = 11;
      for (unsigned s = 0; s < 1024u; ++s) {
        double sum = 0;
        for (int i = 0; i < 10; ++i)
          if (s >> i & 1u) sum += eta2[i];
        if (sum >= theta * total) smallest = std::min(smallest, __builtin_popcount(s));
      }
      EXPECT_EQ(count, smallest) << "trial " << trial << ", theta = " << theta;
      // every marked indicator is at least every unmarked one
      double min_marked = INFINITY, max_unmarked = 0;
      for (int i = 0; i < 10; ++i) {
        if (marked[i]) min_marked = std::min(min_marked, eta2[i]);
        else max_unmarked = std::max(max_unmarked, eta2[i]);
      }
      EXPECT_GE(min_marked, max_unmarked) << "theta = " << theta;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The singular exponent at the punch's corners

// The equation's limits: a rigid wedge (alpha = 1) gives the flat punch's square root; a
// half-plane on a half-plane (phi = pi) 1/2 whatever the materials; a rigid base (alpha = -1)
// no root below 1.
TEST(WedgeExponent, limits_of_the_characteristic_equation) {
  EXPECT_NEAR(chapter10::wedge_on_half_plane_exponent(1.0, pi / 2), 0.5, 1e-10);
  for (double alpha : {-0.9, 0.0, 0.7})
    EXPECT_NEAR(chapter10::wedge_on_half_plane_exponent(alpha, pi), 0.5, 1e-8) << "alpha = " << alpha;
  EXPECT_EQ(chapter10::wedge_on_half_plane_exponent(-1.0, pi / 2), 1.0);
}

// Values at a right-angled wedge (the punch): equal materials 0.77401 (an 8 x 8 determinant of
// Williams' eigenproblem, solved apart from the chapter, gives 0.7740), the chapter's default
// materials (E1 = 1, nu1 = 0.3 on E2 = 3, nu2 = 0.25: a softer wedge, a weaker singularity) and
// the punch's (E1 = 10 on E2 = 1, nu = 0.3 both: alpha = 9/11).
TEST(WedgeExponent, right_angled_wedge_values) {
  EXPECT_NEAR(chapter10::wedge_on_half_plane_exponent(0.0, pi / 2), 0.77401, 1e-4);
  const double a_default = chapter10::dundurs_alpha(1, 0.3, 3, 0.25);
  EXPECT_NEAR(chapter10::wedge_on_half_plane_exponent(a_default, pi / 2), 0.88962, 1e-4);
  const double a_punch = chapter10::dundurs_alpha(10, 0.3, 1, 0.3);
  EXPECT_NEAR(a_punch, 9.0 / 11, 1e-14);
  EXPECT_NEAR(chapter10::wedge_on_half_plane_exponent(a_punch, pi / 2), 0.55574, 1e-4);
}

// Dundurs' alpha swaps sign with the bodies, is zero for equal plane-strain moduli E / (1 - nu^2)
// (even with different E and nu), lies in (-1, 1), and does not see the unit of E.
TEST(WedgeExponent, dundurs_alpha_is_antisymmetric_and_zero_for_equal_plane_strain_moduli) {
  for (auto [E1, nu1, E2, nu2] : {std::array<double, 4>{1, 0.3, 3, 0.25}, {10, 0.3, 1, 0.3}, {1e-6, 0.1, 1e6, 0.45}}) {
    const double a = chapter10::dundurs_alpha(E1, nu1, E2, nu2);
    EXPECT_DOUBLE_EQ(chapter10::dundurs_alpha(E2, nu2, E1, nu1), -a);
    EXPECT_GT(a, -1.0);
    EXPECT_LT(a, 1.0);
    EXPECT_NEAR(chapter10::dundurs_alpha(1e5 * E1, nu1, 1e5 * E2, nu2), a, 1e-14);
  }
  EXPECT_EQ(chapter10::dundurs_alpha(2, 0.3, 2, 0.3), 0.0);
  // E / (1 - nu^2) equal: 0.91 / (1 - 0.09) = 1 = 0.75 / (1 - 0.25)
  EXPECT_NEAR(chapter10::dundurs_alpha(0.91, 0.3, 0.75, 0.5), 0.0, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Gamma_c where both bodies have it (the punch)

namespace {

chapter10::SceneOptions punch_options() {
  chapter10::SceneOptions s;  // as options.cpp sets them for --scene punch
  s.name = "punch";
  s.n0 = 4;
  s.bodies.h_ratio = 2;
  s.bodies.E1 = 10;
  s.bodies.E2 = 1;
  s.bodies.nu2 = 0.3;
  return s;
}

mortar::TwoBodies first_bodies(const chapter10::Scene& scene, int refinements = 0) {
  return mortar::TwoBodies({mortar::rectangle_mesh(scene.first_mesh(0, refinements)), scene.material(0)},
                           {mortar::rectangle_mesh(scene.first_mesh(1, refinements)), scene.material(1)});
}

}  // namespace

// Body 2 reaches beyond body 1: both traces are cut to (L/2 - L/8, L/2 + L/8), and D 1 = M 1 row
// by row (int psi_i over the overlap, the same from both sides): a constant jump is carried
// exactly, the patch test. Both choices of the non-mortar body, the first meshes and two
// uniformly refined ones.
TEST(OverlapDualInterface, punch_traces_end_at_the_corners_and_carry_a_constant) {
  const chapter10::Scene scene(punch_options());
  const double L = scene.options().bodies.L;
  for (int refinements : {0, 1, 3})
    for (int nonmortar : {0, 1}) {
      const mortar::TwoBodies bodies = first_bodies(scene, refinements);
      const mortar::ContactInterface g = chapter10::overlap_dual_interface(bodies, nonmortar);
      const std::string what = "refinements " + std::to_string(refinements) + ", non-mortar body " +
                               std::to_string(nonmortar + 1);
      for (const mortar::InterfaceTrace* t : {&g.nonmortar_trace, &g.mortar_trace}) {
        EXPECT_NEAR(t->x.front(), L / 2 - L / 8, 1e-14) << what;
        EXPECT_NEAR(t->x.back(), L / 2 + L / 8, 1e-14) << what;
        EXPECT_EQ(t->x.size(), t->nodes.size()) << what;
      }
      // body 1's whole bottom, body 2's top between the corners: h2 = 2 h1 at every level
      const int n1 = 4 << refinements;
      EXPECT_EQ((nonmortar == 0 ? g.nonmortar_trace : g.mortar_trace).num_elements(), n1) << what;
      EXPECT_EQ((nonmortar == 0 ? g.mortar_trace : g.nonmortar_trace).num_elements(), n1 / 2) << what;
      const Eigen::VectorXd d = g.matrices.D * Eigen::VectorXd::Ones(g.matrices.D.cols());
      const Eigen::VectorXd m = g.matrices.M * Eigen::VectorXd::Ones(g.matrices.M.cols());
      ASSERT_EQ(d.size(), m.size()) << what;
      ASSERT_GT(d.size(), 0) << what;
      for (int i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i], m[i], 1e-14) << what << ", row " << i;
      EXPECT_NEAR(d.sum(), L / 4, 1e-14) << what;  // the dual basis sums to 1 on the overlap
      EXPECT_NEAR(m.sum(), L / 4, 1e-14) << what;
    }
}

// Body 2 with 7 columns on (0, 1): no node at L/2 -+ L/8, so there is no common end of the two
// traces; refused with a message, never a silently shifted contact line.
TEST(OverlapDualInterface, an_end_that_is_not_a_node_throws) {
  const chapter10::Scene scene(punch_options());
  mortar::RectangleSpec s2 = scene.first_mesh(1);
  s2.nx = 7;
  const mortar::TwoBodies bodies({mortar::rectangle_mesh(scene.first_mesh(0)), scene.material(0)},
                                 {mortar::rectangle_mesh(s2), scene.material(1)});
  for (int nonmortar : {0, 1}) {
    try {
      chapter10::overlap_dual_interface(bodies, nonmortar);
      ADD_FAILURE() << "no exception for non-mortar body " << nonmortar + 1;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("does not end at nodes of both bodies"), std::string::npos) << e.what();
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The adaptive loop

namespace {

chapter10::SceneOptions hertz_options(int n0) {
  chapter10::SceneOptions s;
  s.name = "hertz-exact";
  s.n0 = n0;
  return s;
}

chapter10::LoopOptions steps(int max_steps) {
  chapter10::LoopOptions o;
  o.max_steps = max_steps;
  o.target = 1e-12;  // never reached: every run takes max_steps
  o.nonmortar = 0;   // body 1, the softer (E1 = 1 < E2 = 3), as the program chooses
  o.snapshot_steps.clear();
  return o;
}

}  // namespace

// Nested iteration changes where Newton starts, not where it ends: six adaptive steps on
// hertz-exact (n0 = 8), started from the previous step and from nothing, give the same meshes,
// the same strain energy at every step (to 1e-10) and the same last displacement (to 1e-8), and
// the nested start takes no more Newton steps in all (measured: nested 2, 1, 3, 2, 1, 1 = 10,
// cold 2, 2, 3, 2, 3, 3 = 15).
TEST(AdaptiveLoop, nested_start_gives_the_cold_start_answer_in_no_more_newton_steps) {
  const chapter10::Scene scene(hertz_options(8));
  chapter10::LoopOptions o = steps(6);
  o.nested = true;
  const chapter10::LoopResult nested = chapter10::run_adaptive_loop(scene, o);
  o.nested = false;
  const chapter10::LoopResult cold = chapter10::run_adaptive_loop(scene, o);
  ASSERT_EQ(nested.steps.size(), 6u);
  ASSERT_EQ(cold.steps.size(), 6u);
  int newton_nested = 0, newton_cold = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    const chapter10::StepRecord &a = nested.steps[k], &b = cold.steps[k];
    EXPECT_EQ(a.dofs, b.dofs) << "step " << k;
    EXPECT_NEAR(a.strain_energy, b.strain_energy, 1e-10 * b.strain_energy) << "step " << k;
    EXPECT_EQ(a.active_rows, b.active_rows) << "step " << k;
    newton_nested += a.newton_steps;
    newton_cold += b.newton_steps;
    std::printf("step %zu: %d dofs, Newton steps nested %d, cold %d\n", k, a.dofs, a.newton_steps, b.newton_steps);
  }
  ASSERT_EQ(nested.last->u.size(), cold.last->u.size());
  EXPECT_LE((nested.last->u - cold.last->u).norm(), 1e-8 * cold.last->u.norm());
  EXPECT_LE(newton_nested, newton_cold);
  std::printf("Newton steps in all: nested %d, cold %d\n", newton_nested, newton_cold);
}

// The estimator on the exact Hertz scene (default sizes, n0 = 10): the effectivity
// eta / ||u - u_h|| over 20 adaptive steps (222 to 22340 dofs) and 5 uniform levels (222 to 40844
// dofs) stays in a band: measured 2.7244 to 3.7819 (ratio 1.39), pinned at 0.9 x the smallest and
// 1.1 x the largest. It drifts both ways: down along the adaptive steps (3.61 to 2.72), up along
// the uniform levels (3.47 to 3.78). The adaptive energy error falls like N^-1/2 over the last
// factor 16 in N (measured 0.512; band [0.45, 0.6]; uniform 0.457).
TEST(AdaptiveLoop, hertz_exact_effectivity_band_and_adaptive_rate) {
  const chapter10::Scene scene(hertz_options(10));
  chapter10::LoopOptions o = steps(20);
  const chapter10::LoopResult adaptive = chapter10::run_adaptive_loop(scene, o);
  // five uniform levels: the sixth would pass max_dofs
  const mortar::Mesh m1 = mortar::rectangle_mesh(scene.first_mesh(0, 4)), m2 = mortar::rectangle_mesh(scene.first_mesh(1, 4));
  o.max_dofs = 2.0 * (m1.num_dofs() + m2.num_dofs());
  const chapter10::LoopResult uniform = chapter10::run_uniform_levels(scene, o, 1e-12);
  ASSERT_EQ(adaptive.steps.size(), 20u);
  ASSERT_EQ(uniform.steps.size(), 5u);
  double lo = INFINITY, hi = 0;
  for (const chapter10::LoopResult* run : {&adaptive, &uniform})
    for (const chapter10::StepRecord& r : run->steps) {
      ASSERT_TRUE(std::isfinite(r.effectivity)) << "step " << r.step;
      lo = std::min(lo, r.effectivity);
      hi = std::max(hi, r.effectivity);
    }
  const double rate = chapter10::rate_in_n(adaptive, "error");
  for (const chapter10::LoopResult* run : {&adaptive, &uniform})
    for (const chapter10::StepRecord& r : run->steps)
      std::printf("%s %2d: %7d dofs, err %.4e, effectivity %.4f\n", run == &adaptive ? "adaptive" : "uniform", r.step,
                  r.dofs, r.rel_err_energy, r.effectivity);
  std::printf("effectivity from %.4f to %.4f; adaptive rate in N %.4f, uniform %.4f\n", lo, hi, rate,
              chapter10::rate_in_n(uniform, "error"));
  EXPECT_GE(lo, 0.9 * 2.7244);
  EXPECT_LE(hi, 1.1 * 3.7819);
  EXPECT_GE(rate, 0.45);
  EXPECT_LE(rate, 0.6);
}
