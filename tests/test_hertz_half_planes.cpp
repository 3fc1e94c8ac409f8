// The exact Hertz field of chapter 5's hertz-exact scene, checked against the unilateral contact
// problem itself (check_exact_contact, finite differences) and against an independent closed
// form of its stresses (McEwen 1949, as in Johnson, Contact Mechanics, section 2.7), without any
// solver.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/contact/exact_contact_check.hpp"
#include "common/contact/hertz_half_planes.hpp"
#include "common/contact/manufactured_contact.hpp"
#include "common/fem/mesh.hpp"
#include "common/fem/p2_elasticity.hpp"

using namespace mortar;

namespace {
constexpr double pi = 3.14159265358979323846;
const double x0 = 0.5, a = std::sqrt(2.0) / 6, R = 1;

struct Pair {
  double E1, nu1, E2, nu2;
};
const Pair pairs[] = {{1, 0.3, 1, 0.3}, {1, 0.3, 3, 0.25}, {1e6, 0.2, 1, 0.45}, {1e-3, 0.49, 5, 0.0}};

HertzHalfPlanes hertz(const Pair& c) { return {Material(c.E1, c.nu1), Material(c.E2, c.nu2), x0, a, R}; }

void print(const char* what, const ExactContactResiduals& r) {
  std::printf("%s: gradient %.2e, equilibrium %.2e, boundary %.2e, traction %.2e, sign %.2e, closed gap %.2e, "
              "penetration %.2e\n", what, r.gradient, r.equilibrium, r.boundary, r.traction, r.sign, r.closed_gap,
              r.penetration);
}

// The same field with one ingredient changed by a relative 1e-6: what the check must see.
class Perturbed : public ExactContact {
 public:
  enum class What { pressure, dirichlet_data, field, body1_data, edge_branch };
  Perturbed(const HertzHalfPlanes& h, What w) : ExactContact(h.material(0), h.material(1)), h_(h), w_(w) {}
  Eigen::Vector2d u(int l, const Eigen::Vector2d& p) const override {
    const Eigen::Vector2d u = h_.u(l, p);
    switch (w_) {
      case What::pressure: return u;
      case What::body1_data:  // body 1 only, by 1e-4 of its own size
        return l == 0 ? Eigen::Vector2d(u + 1e-4 * h_.u(0, {0.0, 0.0}).norm() * Eigen::Vector2d(p.x() * p.x(), 0.0)) : u;
      case What::edge_branch:  // a wrong branch of the logarithm on Gamma_c left of the zone
        return p.y() == 0 && p.x() < h_.centre() - h_.half_width() ? Eigen::Vector2d(u + 1e-6 * Eigen::Vector2d(u.norm(), 0)) : u;
      default: return u + eps_u() * Eigen::Vector2d(p.x() * p.x(), 0.0);  // not an elastic field
    }
  }
  Eigen::Matrix2d grad_u(int l, const Eigen::Vector2d& p) const override {
    Eigen::Matrix2d G = h_.grad_u(l, p);
    if (w_ == What::field) G(0, 0) += eps_u() * 2 * p.x();  // u and grad u stay one field
    return G;
  }
  Eigen::Vector2d body_force(int l, const Eigen::Vector2d& p) const override { return h_.body_force(l, p); }
  double pressure(double x) const override { return h_.pressure(x) * (w_ == What::pressure ? 1 + 1e-6 : 1.0); }

 private:
  double eps_u() const { return 1e-6 * h_.gap(0.0); }  // 1e-6 of the displacements on Gamma_c
  const HertzHalfPlanes& h_;
  What w_;
};

// sigma of a half-plane under the Hertz pressure in McEwen's closed form, depth z > 0 (Johnson,
// Contact Mechanics, section 2.7): independent of the potential the library uses. The sign of
// sigma_xz is that of a frame with z into the body, as Flamant's point load -P at the origin
// gives sigma_xz = -(2P/pi) x z^2 / r^4 (negative on the side x > 0).
Eigen::Matrix2d mcewen_stress(double X, double z, double p0) {
  const double s = a * a - X * X + z * z, root = std::sqrt(s * s + 4 * X * X * z * z);
  const double m = std::sqrt(0.5 * (root + s)), n = std::copysign(std::sqrt(0.5 * (root - s)), X);
  const double q = (z * z + n * n) / (m * m + n * n), k = p0 / a;
  Eigen::Matrix2d S;
  const double sxx = -k * (m * (1 + q) - 2 * z), szz = -k * m * (1 - q);
  const double sxz = -k * n * (m * m - z * z) / (m * m + n * n);
  S << sxx, sxz, sxz, szz;
  return S;
}
}  // namespace

TEST(HertzHalfPlanes, is_the_exact_solution_of_unilateral_contact_with_the_hertz_gap) {
  for (const Pair& c : pairs) {
    const HertzHalfPlanes h = hertz(c);
    const ExactContactResiduals r = check_exact_contact(h, [&](double x) { return h.gap(x); }, 1.0, 1.0, 1.0);
    print("hertz", r);
    EXPECT_LT(r.worst(), 1e-10) << "E1 = " << c.E1 << ", E2 = " << c.E2;
    // and on a flat box: the field does not depend on the box
    EXPECT_LT(check_exact_contact(h, [&](double x) { return h.gap(x); }, 1.0, 0.25, 0.5).worst(), 1e-10);
  }
}

TEST(HertzHalfPlanes, check_fails_when_the_gap_the_pressure_or_the_dirichlet_data_change) {
  const HertzHalfPlanes h = hertz(pairs[1]);
  const double shift = 1e-6 * h.gap(0.0);
  const ExactContactResiduals gap = check_exact_contact(h, [&](double x) { return h.gap(x) + shift; }, 1, 1, 1);
  const ExactContactResiduals narrow =  // a wider parabola: the gap no longer closes on the zone
      check_exact_contact(h, [&](double x) { return h.gap(x) * (1 - 1e-6); }, 1, 1, 1);
  const ExactContactResiduals pressure = check_exact_contact(Perturbed(h, Perturbed::What::pressure),
                                                             [&](double x) { return h.gap(x); }, 1, 1, 1);
  const ExactContactResiduals data = check_exact_contact(Perturbed(h, Perturbed::What::dirichlet_data),
                                                         [&](double x) { return h.gap(x); }, 1, 1, 1);
  const ExactContactResiduals field = check_exact_contact(Perturbed(h, Perturbed::What::field),
                                                          [&](double x) { return h.gap(x); }, 1, 1, 1);
  print("gap + 1e-6", gap);
  print("gap * (1 - 1e-6)", narrow);
  print("pressure * (1 + 1e-6)", pressure);
  print("u + 1e-6 x^2 (data only)", data);
  print("u + 1e-6 x^2 (field)", field);
  EXPECT_GT(gap.closed_gap, 1e-8);
  EXPECT_GT(narrow.closed_gap, 1e-9);
  EXPECT_GT(pressure.traction, 1e-7);
  EXPECT_GT(data.gradient, 1e-8);
  EXPECT_GT(field.equilibrium, 1e-8);
  // each body against its own sizes: a stiff body's data are checked as closely as a soft one's
  const HertzHalfPlanes stiff = hertz(pairs[2]);  // E1/E2 = 1e6
  const ExactContactResiduals body1 = check_exact_contact(Perturbed(stiff, Perturbed::What::body1_data),
                                                          [&](double x) { return stiff.gap(x); }, 1, 1, 1);
  print("body 1 of a stiff pair, u + 1e-4 of its size (data only)", body1);
  EXPECT_GT(body1.gradient, 1e-6);
  // u on Gamma_c is compared with its limit from inside: a branch error there is seen
  const ExactContactResiduals branch = check_exact_contact(Perturbed(h, Perturbed::What::edge_branch),
                                                           [&](double x) { return h.gap(x); }, 1, 1, 1);
  print("u_x on Gamma_c left of the zone + 1e-6 |u|", branch);
  EXPECT_GT(branch.boundary, 1e-7);
}

// Far from the zone the potential is evaluated without cancellation: on the axis under the
// centre sigma_zz = -p0 a / sqrt(a^2 + z^2) (McEwen), here at depths up to 10^4 a.
TEST(HertzHalfPlanes, stress_on_the_axis_is_accurate_far_below_the_zone) {
  const HertzHalfPlanes h = hertz(pairs[0]);
  for (double depth : {0.5, 10.0, 1e2, 1e4}) {
    const double z = depth * a, expected = -h.peak_pressure() * a / std::sqrt(a * a + z * z);
    EXPECT_NEAR(h.stress(0, {x0, z})(1, 1), expected, 1e-13 * std::fabs(expected)) << "z = " << depth << " a";
  }
}

TEST(HertzHalfPlanes, stresses_agree_with_mcewens_closed_form) {
  for (const Pair& c : pairs) {
    const HertzHalfPlanes h = hertz(c);
    for (double X : {-0.7, -a - 1e-3, -0.1, 0.0, 0.05, a - 1e-3, a + 0.02, 0.45})
      for (double z : {1e-3, 0.03, 0.2, 0.9}) {
        const Eigen::Matrix2d expected = mcewen_stress(X, z, h.peak_pressure());
        // body 1 is the half-plane itself; body 2 its mirror: sigma_xy changes sign
        EXPECT_LT((h.stress(0, {x0 + X, z}) - expected).norm(), 1e-12 * h.peak_pressure()) << X << " " << z;
        Eigen::Matrix2d mirrored = expected;
        mirrored(0, 1) = mirrored(1, 0) = -expected(0, 1);
        EXPECT_LT((h.stress(1, {x0 + X, -z}) - mirrored).norm(), 1e-12 * h.peak_pressure()) << X << " " << z;
      }
  }
}

TEST(HertzHalfPlanes, is_plane_strain_hertz_with_p0_from_a_and_R) {
  for (const Pair& c : pairs) {
    const HertzHalfPlanes h = hertz(c);
    const double e_star = 1 / ((1 - c.nu1 * c.nu1) / c.E1 + (1 - c.nu2 * c.nu2) / c.E2);
    EXPECT_NEAR(h.e_star(), e_star, 1e-14 * e_star);
    EXPECT_NEAR(h.peak_pressure(), a * e_star / (2 * R), 1e-14 * h.peak_pressure());
    const double P = h.total_force(1.0);
    EXPECT_NEAR(P, pi * a * h.peak_pressure() / 2, 1e-14 * P);
    // the half-width of plane-strain Hertz at that force, a = sqrt(4 P R / (pi E*))
    EXPECT_NEAR(std::sqrt(4 * P * R / (pi * e_star)), a, 1e-13);
    EXPECT_DOUBLE_EQ(h.pressure(x0), h.peak_pressure());
    EXPECT_EQ(h.pressure(x0 + a * 1.0000001), 0.0);
    // rigid motions fixed at the centre of the zone: u = 0 there, on both bodies
    for (int l = 0; l < 2; ++l) EXPECT_LT(h.u(l, {x0, 0.0}).norm(), 1e-16);
  }
}

TEST(HertzHalfPlanes, gap_opens_like_the_power_three_halves_outside_the_zone) {
  const HertzHalfPlanes h = hertz(pairs[1]);
  for (double sign : {-1.0, 1.0}) {
    for (double d : {1e-6, 1e-3, 0.05, 0.3}) {
      const double x = x0 + sign * (a + d);
      const double open = h.gap(x) - h.normal_jump(x);
      EXPECT_GT(open, 0.0) << x;
      EXPECT_NEAR(open, h.open_gap(x), 1e-11 * h.gap(0.0)) << x;
    }
    // the closed form is continuous where it changes from the series to the direct formula
    const double switch_at = a * (1 + 1e-3);
    EXPECT_NEAR(h.open_gap(x0 + sign * switch_at * (1 - 1e-13)), h.open_gap(x0 + sign * switch_at * (1 + 1e-13)),
                1e-9 * h.open_gap(x0 + sign * switch_at));
    // (|X| - a)^{3/2}: the exponent between d = 1e-6 and 1e-5
    const double d1 = 1e-6, d2 = 1e-5;
    const double exponent = std::log(h.open_gap(x0 + sign * (a + d2)) / h.open_gap(x0 + sign * (a + d1))) / std::log(10.0);
    EXPECT_NEAR(exponent, 1.5, 1e-4);
    // and the pressure like (a - |X|)^{1/2} inside
    const double inside = std::log(h.pressure(x0 + sign * (a - d2)) / h.pressure(x0 + sign * (a - d1))) / std::log(10.0);
    EXPECT_NEAR(inside, 0.5, 1e-4);
  }
}

TEST(ExactContactCheck, passes_the_signorini_and_bilateral_solutions_of_chapter_5) {
  // and shows what separates them from Hertz: the signorini field is also the solution with no
  // gap at all (its jump is zero everywhere, the glued problem's solution), the Hertz field is not
  const Material m1(1, 0.3), m2(3, 0.25);
  const ManufacturedContact signorini(m1, m2, signorini_profile(1.0, signorini_contact_point(1.0)), 1.0);
  const ExactContactResiduals r = check_exact_contact(signorini, [](double x) { return signorini_gap(1.0, x); }, 1, 1, 1);
  print("signorini", r);
  EXPECT_LT(r.worst(), 1e-10);
  const ManufacturedContact bilateral(m1, m2, 1.0);
  EXPECT_LT(check_exact_contact(bilateral, [](double) { return 0.0; }, 1, 1, 1).worst(), 1e-10);
  EXPECT_LT(check_exact_contact(signorini, [](double) { return 0.0; }, 1, 1, 1).worst(), 1e-10);
  const HertzHalfPlanes h(m1, m2, x0, a, R);
  const ExactContactResiduals glued = check_exact_contact(h, [](double) { return 0.0; }, 1, 1, 1);
  print("hertz, no gap", glued);
  EXPECT_GT(glued.closed_gap, 1e-3);  // [u.n] = X^2 / (2R) in the zone, not 0
  EXPECT_GT(glued.penetration, 1e-3);  // and beyond it the bodies would overlap
}

// What the contact edge leaves to a finite element space: the nodal interpolant of body 1's
// exact field in energy, on squares of side h around the zone. u is in H^{5/2 - eps} and no
// better (the power r^{3/2} at the edges): P1 keeps its h, P2 falls from h^2 to h^{3/2}.
// Measured, h = 1/8 to 1/512: P1 local rates 0.91 rising to 1.00; P2 1.47, 1.39, 1.60, 1.47,
// 1.42, 1.59, swinging around 3/2 with where the edges cut their elements. Here h = 1/16 to
// 1/128, slopes 0.97 (P1) and 1.50 (P2).
TEST(HertzHalfPlanes, contact_edge_caps_the_p2_interpolant_at_h_to_the_three_halves) {
  const HertzHalfPlanes h = hertz(pairs[0]);
  const ExactSolution body1 = h.exact(0);
  for (int degree : {1, 2}) {
    std::vector<double> errors, sizes;
    for (int n = 16; n <= 128; n *= 2) {
      RectangleSpec spec;
      spec.nx = spec.ny = n;
      const Mesh p1 = rectangle_mesh(spec);  // (0, 1) x (0, 1): body 1 of the scene
      const Mesh mesh = degree == 1 ? p1 : p2_mesh(p1);
      Eigen::VectorXd u(mesh.num_dofs());
      for (int a = 0; a < mesh.num_nodes(); ++a) u.segment<2>(2 * a) = h.u(0, mesh.nodes[a]);
      errors.push_back(error_norms(mesh, h.material(0), u, body1).relative_energy());
      sizes.push_back(1.0 / n);
    }
    std::printf("P%d interpolant of the Hertz field, relative energy error:", degree);
    for (std::size_t k = 0; k < errors.size(); ++k) std::printf(" %.3e", errors[k]);
    std::printf("; local rates:");
    for (std::size_t k = 1; k < errors.size(); ++k)
      std::printf(" %.3f", std::log(errors[k] / errors[k - 1]) / std::log(sizes[k] / sizes[k - 1]));
    std::printf("\n");
    // least-squares slope over the four sizes: where the edges fall in their elements
    // changes from level to level, and the local rates of P2 swing around 3/2 with it
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = errors.size() - 4; k < errors.size(); ++k) {
      const double x = std::log(sizes[k]), y = std::log(errors[k]);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double rate = (4 * sxy - sx * sy) / (4 * sxx - sx * sx);
    std::printf("P%d: slope over the four sizes %.3f\n", degree, rate);
    if (degree == 1) EXPECT_NEAR(rate, 1.0, 0.05);
    else EXPECT_NEAR(rate, 1.5, 0.05);
  }
}
