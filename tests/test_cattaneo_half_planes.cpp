// The exact Cattaneo-Mindlin field of chapter 8's cattaneo-exact scene, checked without any
// solver: against the frictional contact problem itself (check_exact_contact: equilibrium,
// grad u, the tractions sigma_22 = -p and sigma_12 = q on Gamma_c from both sides, the closed
// Hertz gap), against an independent superposition of Flamant's tangential line loads
// integrated numerically (Johnson, Contact Mechanics, (2.19)), and against Coulomb's law: stick
// where |q| < F p, slip in the direction of q where q = F p, the slip growing with Q.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "common/contact/cattaneo_half_planes.hpp"
#include "common/contact/exact_contact_check.hpp"
#include "common/fem/quadrature.hpp"

using namespace mortar;

namespace {
constexpr double pi = 3.14159265358979323846;
const double x0 = 0.5, a = std::sqrt(2.0) / 6, R = 1, F = 0.3;

struct Pair {
  double E1, nu1, E2, nu2;
};
// Dundurs' beta = 0: one material, a stiff one, and two materials with (1 - 2 nu)/mu alike
// (E2 = 0.8 (1.1) E1 / (0.4 (1.3)) with nu1 = 0.3, nu2 = 0.1)
const Pair pairs[] = {{1, 0.3, 1, 0.3}, {1e6, 0.2, 1e6, 0.2}, {1, 0.3, 0.8 * 2.2 / 1.04, 0.1}};

CattaneoHalfPlanes cattaneo(const Pair& c, double q_ratio) {
  return {Material(c.E1, c.nu1), Material(c.E2, c.nu2), x0, a, R, F, q_ratio};
}

// The stress at (X, z), z > 0, of a half-plane whose edge carries the tangential traction t(s)
// (force per length on the body, in +x): Flamant's tangential line load (Johnson (2.19),
// sigma_x = -(2Q/pi) x^3/r^4, sigma_z = -(2Q/pi) x z^2/r^4, tau_xz = -(2Q/pi) x^2 z/r^4)
// superposed over the elliptical loads of q, each integrated in s = b sin(theta) (no square
// root left in the integrand) by 8-point Gauss on 2000 pieces.
Eigen::Matrix2d flamant_shear_stress(double X, double z, double b, double k) {
  const SegmentRule g = gauss_legendre(8);
  const int pieces = 2000;
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  for (int e = 0; e < pieces; ++e)
    for (std::size_t q = 0; q < g.points.size(); ++q) {
      const double theta = -0.5 * pi + pi * (e + g.points[q]) / pieces, w = g.weights[q] * pi / pieces;
      const double s = b * std::sin(theta), load = k * std::cos(theta) * b * std::cos(theta) * w;  // t(s) ds
      const double x = X - s, r2 = x * x + z * z, c = -2 * load / (pi * r2 * r2);
      S(0, 0) += c * x * x * x;
      S(1, 1) += c * x * z * z;
      S(0, 1) += c * x * x * z;
    }
  S(1, 0) = S(0, 1);
  return S;
}
}  // namespace

TEST(CattaneoHalfPlanes, is_the_exact_solution_of_the_contact_problem_with_the_hertz_gap) {
  for (const Pair& c : pairs)
    for (double q_ratio : {0.0, 0.3, 0.6, 0.99}) {
      const CattaneoHalfPlanes m = cattaneo(c, q_ratio);
      const auto gap = [&](double x) { return m.normal().gap(x); };
      const ExactContactResiduals r = check_exact_contact(m, gap, 1.0, 1.0, 1.0);
      EXPECT_LT(r.worst(), 1e-10) << "E2 " << c.E2 << ", Q/(F P) " << q_ratio << ": gradient " << r.gradient
                                  << ", equilibrium " << r.equilibrium << ", boundary " << r.boundary << ", traction "
                                  << r.traction << ", closed gap " << r.closed_gap << ", penetration " << r.penetration;
      EXPECT_LT(check_exact_contact(m, gap, 1.0, 0.25, 0.5).worst(), 1e-10);  // any box
    }
}

// The traction residual sees the shear: the Hertz field alone, taken as a Cattaneo solution,
// fails it by the size of q.
TEST(CattaneoHalfPlanes, the_check_sees_a_missing_shear) {
  const CattaneoHalfPlanes m = cattaneo(pairs[0], 0.6);
  const HertzHalfPlanes& h = m.normal();
  double worst = 0;
  for (int k = 0; k <= 200; ++k) {
    const double x = x0 - a + 2 * a * k / 200.0;
    worst = std::max(worst, std::fabs(h.stress(0, {x, 0.0})(0, 1) - m.shear(x)));
  }
  EXPECT_GT(worst, 0.1 * F * h.peak_pressure());
}

TEST(CattaneoHalfPlanes, stresses_agree_with_superposed_flamant_line_loads) {
  for (const Pair& c : pairs) {
    const CattaneoHalfPlanes m = cattaneo(c, 0.6);
    const double Fp0 = F * m.normal().peak_pressure(), cs = m.stick_half_width();
    for (double X : {-0.4, -a - 1e-3, -0.1, 0.0, 0.07, cs + 1e-3, a + 0.02})
      for (double z : {0.02, 0.1, 0.5}) {
        // body 1 carries -q on its edge (it feels -lambda_t), body 2 +q
        const Eigen::Matrix2d body1 = -flamant_shear_stress(X, z, a, Fp0) - flamant_shear_stress(X, z, cs, -Fp0 * cs / a);
        const Eigen::Matrix2d shear1 = m.stress(0, {x0 + X, z}) - m.normal().stress(0, {x0 + X, z});
        EXPECT_LT((shear1 - body1).norm(), 1e-9 * Fp0) << "body 1 at X " << X << ", z " << z;
        // body 2 is the mirror image (sigma_xy changes sign) of a half-plane carrying +q
        Eigen::Matrix2d body2 = -body1;
        body2(0, 1) = body2(1, 0) = body1(0, 1);
        const Eigen::Matrix2d shear2 = m.stress(1, {x0 + X, -z}) - m.normal().stress(1, {x0 + X, -z});
        EXPECT_LT((shear2 - body2).norm(), 1e-9 * Fp0) << "body 2 at X " << X << ", z " << z;
      }
  }
}

TEST(CattaneoHalfPlanes, sticks_below_coulombs_threshold_and_slips_on_it_in_the_shears_direction) {
  const CattaneoHalfPlanes m = cattaneo(pairs[2], 0.6);
  const double c = m.stick_half_width(), p0 = m.normal().peak_pressure();
  const double scale = m.normal().gap(x0 + a);  // the size of the displacements on Gamma_c
  EXPECT_NEAR(c, a * std::sqrt(0.4), 1e-15);
  for (int k = 1; k < 1000; ++k) {
    const double X = -a + 2 * a * k / 1000.0, x = x0 + X, q = m.shear(x), s = F * m.pressure(x);
    if (std::fabs(X) < c) {
      EXPECT_LT(q, s) << X;
      EXPECT_GT(q, 0.0) << X;
      EXPECT_NEAR(m.slip(x), 0.0, 1e-13 * scale) << X;
    } else {
      EXPECT_NEAR(q, s, 1e-15 * p0) << X;
      EXPECT_GT(m.slip(x), 1e-6 * scale) << X;  // the slip has the sign of q
    }
  }
  // int q = Q = F P (1 - c^2/a^2), by Gauss on the stick zone and each side of the slip zone
  const SegmentRule g = gauss_legendre(8);
  double Q = 0;
  for (const auto& [from, to] : {std::pair{-a, -c}, std::pair{-c, c}, std::pair{c, a}})
    for (int e = 0; e < 400; ++e)
      for (std::size_t q = 0; q < g.points.size(); ++q)
        Q += g.weights[q] * (to - from) / 400 * m.shear(x0 + from + (to - from) * (e + g.points[q]) / 400);
  EXPECT_NEAR(Q, m.shear_force(), 1e-6 * m.shear_force());
  EXPECT_NEAR(m.shear_force(), 0.6 * F * m.normal().total_force(1.0), 1e-14);
}

// Coulomb's law is for increments: along Q_1 < Q_2 the slip never decreases and the stick zone
// only shrinks, so each step's field is the answer of that step.
TEST(CattaneoHalfPlanes, slip_grows_with_the_shear_at_every_point) {
  const Pair& c = pairs[0];
  for (double q_ratio : {0.1, 0.4, 0.7}) {
    const CattaneoHalfPlanes before = cattaneo(c, q_ratio), after = cattaneo(c, q_ratio + 0.2);
    for (int k = 0; k <= 400; ++k) {
      const double x = x0 - a + 2 * a * k / 400.0;
      EXPECT_GE(after.slip(x) - before.slip(x), -1e-15) << x;
    }
  }
}

TEST(CattaneoHalfPlanes, refuses_two_materials_whose_shear_moves_the_pressure) {
  EXPECT_THROW(CattaneoHalfPlanes(Material(1, 0.3), Material(3, 0.25), x0, a, R, F, 0.5), std::invalid_argument);
  EXPECT_THROW(cattaneo(pairs[0], 1.0), std::invalid_argument);
  EXPECT_THROW(CattaneoHalfPlanes(Material(1, 0.3), Material(1, 0.3), x0, a, R, 0.0, 0.5), std::invalid_argument);
}
