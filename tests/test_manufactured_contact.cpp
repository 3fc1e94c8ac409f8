// The exact solution of chapters 3-5 checked against the contact problem (1)-(5) itself, by
// finite differences, independently of any solver.
#include <gtest/gtest.h>

#include <cmath>

#include "common/contact/manufactured_contact.hpp"

using namespace mortar;

namespace {
const double h = 1e-5;  // central differences: error O(h^2) = 1e-10 relative

// div sigma by central differences of the exact stress
Eigen::Vector2d div_stress(const ManufacturedContact& m, int l, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ex(h, 0), ey(0, h);
  const Eigen::Matrix2d dx = (m.stress(l, p + ex) - m.stress(l, p - ex)) / (2 * h);
  const Eigen::Matrix2d dy = (m.stress(l, p + ey) - m.stress(l, p - ey)) / (2 * h);
  return {dx(0, 0) + dy(0, 1), dx(1, 0) + dy(1, 1)};
}

struct Pair {
  double E1, nu1, E2, nu2;
};
const Pair pairs[] = {{1, 0.3, 3, 0.25}, {1e6, 0.2, 1, 0.45}, {1e-3, 0.49, 5, 0.0}};
const double xs[] = {0.0, 0.13, 0.5, 0.77, 1.0};
}  // namespace

TEST(ManufacturedContact, satisfies_equilibrium_1_in_both_bodies) {
  for (const Pair& c : pairs) {
    const ManufacturedContact m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), 1.0);
    for (int l = 0; l < 2; ++l)
      for (double x : xs)
        for (double y : {0.1, 0.3}) {
          const Eigen::Vector2d p(x, l == 0 ? y : -y);
          const Eigen::Vector2d f = m.body_force(l, p);
          const double scale = m.stress(l, p).norm() + f.norm();
          EXPECT_LT((div_stress(m, l, p) + f).norm(), 1e-7 * scale) << "body " << l + 1 << " at " << p.transpose();
        }
  }
}

TEST(ManufacturedContact, grad_u_is_the_derivative_of_u) {
  const ManufacturedContact m(Material(1, 0.3), Material(3, 0.25), 1.0);
  for (int l = 0; l < 2; ++l)
    for (double x : xs) {
      const Eigen::Vector2d p(x, l == 0 ? 0.2 : -0.2), ex(h, 0), ey(0, h);
      Eigen::Matrix2d G;
      G.col(0) = (m.u(l, p + ex) - m.u(l, p - ex)) / (2 * h);
      G.col(1) = (m.u(l, p + ey) - m.u(l, p - ey)) / (2 * h);
      EXPECT_LT((G - m.grad_u(l, p)).norm(), 1e-9 * m.grad_u(l, p).norm());
    }
}

TEST(ManufacturedContact, satisfies_the_contact_conditions_3_to_5_on_gamma_c) {
  const Eigen::Vector2d n1(0, -1), n2(0, 1);
  for (const Pair& c : pairs) {
    const ManufacturedContact m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), 1.0);
    for (double x : xs) {
      const Eigen::Vector2d p(x, 0.0);
      const double scale = m.stress(0, p).norm() + m.stress(1, p).norm();
      // (3) u1.n1 + u2.n2 = 0
      EXPECT_NEAR(m.u(0, p).dot(n1) + m.u(1, p).dot(n2), 0.0, 1e-15) << "x = " << x;
      EXPECT_NEAR(m.u(0, p).y(), m.normal_displacement(x), 1e-15);
      // (4) sigma^1 n1 . n1 = sigma^2 n2 . n2 = sigma_N = -pressure
      const Eigen::Vector2d t1 = m.stress(0, p) * n1, t2 = m.stress(1, p) * n2;
      EXPECT_NEAR(t1.dot(n1), t2.dot(n2), 1e-12 * scale) << "x = " << x;
      EXPECT_NEAR(t1.dot(n1), -m.pressure(x), 1e-12 * scale);
      // (5) no tangential stress on either side
      EXPECT_NEAR(t1.x(), 0.0, 1e-12 * scale) << "x = " << x;
      EXPECT_NEAR(t2.x(), 0.0, 1e-12 * scale) << "x = " << x;
      EXPECT_GT(m.pressure(x), 0.0) << "the bodies press on each other everywhere";
    }
    // and the tangential displacement does jump: the bodies slide
    const Eigen::Vector2d q(0.5, 0.0);
    EXPECT_GT(std::fabs(m.u(0, q).x() - m.u(1, q).x()), 1e-3);
  }
}

namespace {
// The unilateral solution on both sides of its contact point x* = 0.6414...
const double signorini_xs[] = {0.0, 0.2, 0.5, 0.6, 0.64, 0.645, 0.7, 0.9, 1.0};
}  // namespace

TEST(ManufacturedContact, signorini_solution_satisfies_equilibrium_1_and_the_law_2) {
  for (const Pair& c : pairs) {
    const ManufacturedContact m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), signorini_profile(1.0, signorini_contact_point(1.0)), 1.0);
    for (int l = 0; l < 2; ++l)
      for (double x : signorini_xs)
        for (double y : {0.05, 0.4}) {
          const Eigen::Vector2d p(x, l == 0 ? y : -y);
          const Eigen::Vector2d f = m.body_force(l, p);
          // finite differences err by O(h^2) of the whole field's size, which near x* is
          // set by the smooth part: scale by the field at x = 0
          const Eigen::Vector2d p0(0.0, p.y());
          const double scale = m.stress(l, p0).norm() + m.body_force(l, p0).norm();
          EXPECT_LT((div_stress(m, l, p) + f).norm(), 1e-7 * scale) << "body " << l + 1 << " at " << p.transpose();
          // (2): sigma = lambda tr(eps) I + 2 mu eps, with eps from finite differences of u
          const Eigen::Vector2d ex(h, 0), ey(0, h);
          Eigen::Matrix2d G;
          G.col(0) = (m.u(l, p + ex) - m.u(l, p - ex)) / (2 * h);
          G.col(1) = (m.u(l, p + ey) - m.u(l, p - ey)) / (2 * h);
          const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
          const Material& mat = m.material(l);
          const Eigen::Matrix2d sigma = mat.lambda() * eps.trace() * Eigen::Matrix2d::Identity() + 2 * mat.mu() * eps;
          EXPECT_LT((sigma - m.stress(l, p)).norm(), 1e-8 * scale) << "at " << p.transpose();
        }
  }
}

TEST(ManufacturedContact, signorini_solution_satisfies_4_5_and_the_unilateral_conditions_9_to_11) {
  const double L = 1.0, x_star = signorini_contact_point(L);
  const Eigen::Vector2d n1(0, -1), n2(0, 1);
  for (const Pair& c : pairs) {
    const ManufacturedContact m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), signorini_profile(L, x_star), L);
    const double p_scale = m.pressure(0.0);
    ASSERT_GT(p_scale, 0.0);
    for (double x : signorini_xs) {
      const Eigen::Vector2d p(x, 0.0);
      const Eigen::Vector2d t1 = m.stress(0, p) * n1, t2 = m.stress(1, p) * n2;
      const double sigma_N = t1.dot(n1), jump = m.u(0, p).dot(n1) + m.u(1, p).dot(n2);
      const double gap = signorini_gap(L, x);
      EXPECT_NEAR(sigma_N, t2.dot(n2), 1e-12 * p_scale) << "(4) at x = " << x;
      EXPECT_NEAR(sigma_N, -m.pressure(x), 1e-12 * p_scale);
      EXPECT_NEAR(t1.x(), 0.0, 1e-12 * p_scale) << "(5) at x = " << x;
      EXPECT_NEAR(t2.x(), 0.0, 1e-12 * p_scale) << "(5) at x = " << x;
      EXPECT_LE(jump, gap + 1e-15) << "(9) at x = " << x;
      EXPECT_LE(sigma_N, 1e-15 * p_scale) << "(10) at x = " << x;
      EXPECT_NEAR(sigma_N * (jump - gap), 0.0, 1e-15 * p_scale) << "(11) at x = " << x;
      // a true contact zone and a true separation zone, meeting at x*
      if (x < x_star) {
        EXPECT_GT(m.pressure(x), 0.0) << "x = " << x;
        EXPECT_EQ(gap, 0.0);
      } else {
        EXPECT_EQ(m.pressure(x), 0.0) << "x = " << x;
        EXPECT_GT(gap - jump, 0.0) << "x = " << x;
      }
    }
  }
}

TEST(ManufacturedContact, signorini_contact_point_is_no_node_of_the_course_meshes) {
  const double x_star = signorini_contact_point(1.0);
  for (int n : {6, 8, 12, 16}) 
    for (int level = 0; level < 12; ++level) {
      const double h = 1.0 / (n << level), t = x_star / h;
      EXPECT_GT(std::fabs(t - std::round(t)), 1e-6) << n << " x 2^" << level << " elements";
    }
}

TEST(ManufacturedContact, flat_ends_profile_has_a_pressure_with_zero_slope_at_both_ends) {
  const ManufacturedContact m(Material(1, 0.3), Material(3, 0.25), flat_ends_profile(1.0), 1.0);
  const double d = 1e-6;
  for (double x : {0.0, 1.0}) {
    const double slope = (m.pressure(x + d) - m.pressure(x - d)) / (2 * d);  // the profile extends past Gamma_c
    EXPECT_LT(std::fabs(slope), 1e-8 * m.pressure(0.5)) << "x = " << x;
  }
  const ManufacturedContact sloped(Material(1, 0.3), Material(3, 0.25), 1.0);
  EXPECT_GT(std::fabs(sloped.pressure(1.0) - sloped.pressure(1.0 - d)) / d, 1e-3 * sloped.pressure(0.5));
}
