#include <gtest/gtest.h>

#include "common/contact/bilateral_contact.hpp"
#include "exercise.hpp"

namespace {
// max over all nodes of |u_h - u| / max |u|, for the discrete patch test of one matching
double patch_error(mortar::Matching matching, const exercise::PatchData& d) {
  mortar::TwoBodyGeometry g;
  g.n1 = 6; g.m1 = 3; g.n2 = 14; g.m2 = 7; g.H2 = d.H2; g.jitter = 0.2;  // h2/h1 = 3/7
  const mortar::TwoBodies b = mortar::make_two_bodies(g, mortar::Material(d.E1, d.nu1), mortar::Material(d.E2, d.nu2));
  const mortar::SceneData scene = mortar::patch_test_scene(b, d.pressure);
  const mortar::BilateralSolution s = mortar::solve_bilateral(
      b, scene, {matching, 0, mortar::SaddleSolver::lu, mortar::fastest_spd_backend()});
  double error = 0, size = 0;
  for (int l = 0; l < 2; ++l)
    for (int a = 0; a < b.body(l).mesh.num_nodes(); ++a) {
      const Eigen::Vector2d exact = exercise::patch_displacement(l, b.body(l).mesh.nodes[a], d);
      const Eigen::Vector2d uh(s.u[b.dof(l, a, 0)], s.u[b.dof(l, a, 1)]);
      error = std::max(error, (uh - exact).norm());
      size = std::max(size, uh.norm());
    }
  return error / size;
}
}  // namespace

TEST(PatchTest, integral_matching_reproduces_your_exact_solution_and_pointwise_does_not) {
  exercise::PatchData d;
  EXPECT_LT(patch_error(mortar::Matching::integral, d), 1e-10);
  EXPECT_GT(patch_error(mortar::Matching::pointwise, d), 1e-4);
  d.E2 = 1e3;
  d.nu1 = 0.45;
  EXPECT_LT(patch_error(mortar::Matching::integral, d), 1e-10);
}
