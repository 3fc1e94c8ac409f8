#include <gtest/gtest.h>

#include "common/contact/bilateral_contact.hpp"
#include "common/fem/p1_elasticity.hpp"
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

// Worked by hand for the default data (E1 = 1, nu1 = 0.3, E2 = 3, nu2 = 0.25, p = 0.01,
// H2 = 0.5), and again in exact rational arithmetic from Hooke's law with sigma_zz = nu p:
// eps^1 = (39/10000, -91/10000), eps^2 = (1/960, -1/320), so
// u^1(1, 0.5) = (39/10000, -489/80000) and u^2(1, -0.25) = (1/960, -1/1280).
TEST(PatchTest, matches_two_points_worked_by_hand) {
  const exercise::PatchData d;
  const Eigen::Vector2d u1 = exercise::patch_displacement(0, Eigen::Vector2d(1.0, 0.5), d);
  const Eigen::Vector2d u2 = exercise::patch_displacement(1, Eigen::Vector2d(1.0, -0.25), d);
  EXPECT_NEAR(u1.x(), 0.0039, 1e-15);
  EXPECT_NEAR(u1.y(), -0.0061125, 1e-15);
  EXPECT_NEAR(u2.x(), 1.0 / 960, 1e-15);
  EXPECT_NEAR(u2.y(), -0.00078125, 1e-15);
}

// The conditions the exact solution must meet, checked on the field itself: its strains (by
// differences, exact for an affine field) through each body's plane-strain law give
// sigma = diag(0, -p); the rollers; u_y continuous across Gamma_c.
TEST(PatchTest, your_field_meets_hookes_law_the_rollers_and_the_contact_condition) {
  exercise::PatchData stiff_below;
  stiff_below.E2 = 1e3;
  stiff_below.nu1 = 0.45;
  for (const exercise::PatchData& d : {exercise::PatchData(), stiff_below}) {
    const double p = d.pressure, h = 0.1;
    for (int l = 0; l < 2; ++l) {
      const mortar::Material material = l == 0 ? mortar::Material(d.E1, d.nu1) : mortar::Material(d.E2, d.nu2);
      const Eigen::Vector2d at = l == 0 ? Eigen::Vector2d(0.7, 0.3) : Eigen::Vector2d(0.7, -0.3);
      const auto u = [&](double dx, double dy) { return exercise::patch_displacement(l, at + Eigen::Vector2d(dx, dy), d); };
      const Eigen::Vector2d du_dx = (u(h, 0) - u(-h, 0)) / (2 * h), du_dy = (u(0, h) - u(0, -h)) / (2 * h);
      const Eigen::Vector3d strain(du_dx.x(), du_dy.y(), du_dy.x() + du_dx.y());  // Voigt: 2 eps_xy last
      const Eigen::Vector3d stress = material.voigt() * strain;
      EXPECT_NEAR(stress[0], 0.0, 1e-10 * p) << "body " << l + 1 << ": sigma_xx";
      EXPECT_NEAR(stress[1], -p, 1e-10 * p) << "body " << l + 1 << ": sigma_yy";
      EXPECT_NEAR(stress[2], 0.0, 1e-10 * p) << "body " << l + 1 << ": sigma_xy";
      for (double y : {0.0, 0.2, 0.45}) {
        const Eigen::Vector2d left(0.0, l == 0 ? y : -y);
        EXPECT_NEAR(exercise::patch_displacement(l, left, d).x(), 0.0, 1e-15) << "body " << l + 1 << ": roller at x = 0";
      }
    }
    for (double x : {0.0, 0.35, 1.0}) {
      EXPECT_NEAR(exercise::patch_displacement(1, Eigen::Vector2d(x, -d.H2), d).y(), 0.0, 1e-15)
          << "roller under body 2, x = " << x;
      EXPECT_NEAR(exercise::patch_displacement(0, Eigen::Vector2d(x, 0.0), d).y(),
                  exercise::patch_displacement(1, Eigen::Vector2d(x, 0.0), d).y(), 1e-15)
          << "[u.n] on Gamma_c, x = " << x;
    }
  }
}

TEST(PatchTest, integral_matching_reproduces_your_exact_solution_and_pointwise_does_not) {
  exercise::PatchData d;
  EXPECT_LT(patch_error(mortar::Matching::integral, d), 1e-10);
  EXPECT_GT(patch_error(mortar::Matching::pointwise, d), 1e-4);
  d.E2 = 1e3;
  d.nu1 = 0.45;
  EXPECT_LT(patch_error(mortar::Matching::integral, d), 1e-10);
}
