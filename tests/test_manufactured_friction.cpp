// The exact solution of chapter 8's manufactured scene, checked against the frictional contact
// problem by finite differences, independently of any solver: equilibrium, grad u, the
// tractions on Gamma_c from both sides, and the friction law on the stick and the slip zone.
#include <gtest/gtest.h>

#include <cmath>

#include "common/contact/exact_contact_check.hpp"
#include "common/contact/manufactured_friction.hpp"

using namespace mortar;

namespace {
struct Pair {
  double E1, nu1, E2, nu2;
};
const Pair pairs[] = {{1, 0.3, 1, 0.3}, {1, 0.3, 3, 0.25}, {1e6, 0.2, 1, 0.45}};
}  // namespace

// The library's check (exact_contact_check.hpp): grad u against u, equilibrium against the
// body force, u on Gamma_c from inside each body, sigma_22 = -p and sigma_12 = tau on Gamma_c.
TEST(ManufacturedFriction, satisfies_equilibrium_and_grad_u_is_the_derivative_of_u) {
  for (double L : {1.0, 1e-3, 1e3})
    for (const Pair& c : pairs) {
      const ManufacturedFriction m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), L, 0.3);
      const ExactContactResiduals r = check_exact_contact(m, [](double) { return 0.0; }, L, 0.5 * L, 0.5 * L);
      EXPECT_LT(r.gradient, 1e-9) << "L " << L << ", E1 " << c.E1;
      EXPECT_LT(r.equilibrium, 1e-8) << "L " << L << ", E1 " << c.E1;
      EXPECT_LT(r.boundary, 1e-12) << "L " << L << ", E1 " << c.E1;
      EXPECT_LT(r.closed_gap, 1e-12) << "L " << L << ", E1 " << c.E1;
      EXPECT_EQ(r.sign, 0.0);
      // sigma_12 = tau on both sides, to round-off: in a body 1e6 times stiffer the slip's own
      // stress, about mu1 C, is 6e5 times p, and cancels to K ~ p: 1e-16 of it is 1e-10 of p
      EXPECT_LT(r.traction, 1e-9) << "L " << L << ", E1 " << c.E1;
    }
}

TEST(ManufacturedFriction, tractions_on_gamma_c_agree_from_both_sides) {
  for (const Pair& c : pairs) {
    const ManufacturedFriction m(Material(c.E1, c.nu1), Material(c.E2, c.nu2), 1.0, 0.3);
    for (double x : {0.0, 0.2, 0.41, 0.42, 0.7, 1.0}) {
      const Eigen::Vector2d p(x, 0.0);
      const Eigen::Matrix2d s1 = m.stress(0, p), s2 = m.stress(1, p);
      // sigma_12 = mu (P + c') adds terms of the size of the whole stress: round-off of it
      const double scale = 1e3 * (s1.norm() + s2.norm());
      EXPECT_NEAR(s1(0, 1), m.shear(x), 1e-12 * scale);
      EXPECT_NEAR(s2(0, 1), m.shear(x), 1e-12 * scale);
      EXPECT_NEAR(s1(1, 1), -m.pressure(x), 1e-12 * scale);
      EXPECT_NEAR(s2(1, 1), -m.pressure(x), 1e-12 * scale);
      EXPECT_NEAR(m.u(0, p).y(), m.u(1, p).y(), 1e-15);                  // closed
      EXPECT_NEAR(m.u(0, p).x() - m.u(1, p).x(), m.slip(x), 1e-15);      // the slip
    }
  }
}

TEST(ManufacturedFriction, sticks_below_the_threshold_and_slips_at_it_with_the_slips_sign) {
  const ManufacturedFriction m(Material(1, 0.3), Material(3, 0.25), 1.0, 0.3);
  const double xc = m.stick_slip_point();
  EXPECT_GT(std::fabs(xc * 1024 - std::round(xc * 1024)), 0.05);  // not a node of dyadic meshes
  bool shear_changes_sign = false;
  for (int k = 0; k <= 1000; ++k) {
    const double x = k / 1000.0, s = m.threshold(x), tau = m.shear(x);
    ASSERT_GT(m.pressure(x), 0);
    if (x < xc) {
      EXPECT_EQ(m.slip(x), 0.0);
      EXPECT_LT(std::fabs(tau), s) << x;
      shear_changes_sign = shear_changes_sign || tau < 0;
    } else {
      EXPECT_GE(m.slip(x), 0.0);
      EXPECT_NEAR(tau, s, 1e-15);
    }
  }
  EXPECT_TRUE(shear_changes_sign);
  EXPECT_GT(m.slip(1.0), 0.0);
}

// The transition is the generic one: the margin F p - tau grows like sqrt(x_c - x) and the slip
// like (x - x_c)^{3/2}, with the constants of the header (K sqrt(x_c) = 1.5 F S, C = 2 eps / sqrt(L)).
// The earlier solution's margin grew like (x_c - x)^2, which this test refuses.
TEST(ManufacturedFriction, the_stick_slip_transition_is_of_square_root_type) {
  for (const Pair& c : pairs) {
    const Material m1(c.E1, c.nu1), m2(c.E2, c.nu2);
    const ManufacturedFriction m(m1, m2, 1.0, 0.3);
    const double xc = m.stick_slip_point();
    const double S = 1e-3 / ((1 - c.nu1 * c.nu1) / c.E1 + (1 - c.nu2 * c.nu2) / c.E2);
    const double K = 1.5 * 0.3 * S / std::sqrt(xc), C = 2e-3;
    // d >= 1e-5: x_c +- d carries x_c's round-off, 1e-16 / d of d
    for (double d : {1e-5, 1e-3, 0.1}) {
      EXPECT_NEAR((m.threshold(xc - d) - m.shear(xc - d)) / std::sqrt(d), K, 1e-9 * K) << d;
      EXPECT_NEAR(m.slip(xc + d) / (d * std::sqrt(d)), C, 1e-9 * C) << d;
    }
  }
}
