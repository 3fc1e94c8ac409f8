#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "common/contact/pressure_norms.hpp"
#include "common/fem/quadrature.hpp"
#include "hertz_best_approximation.hpp"

using namespace mortar;

namespace {
constexpr double pi = 3.14159265358979323846;

// M_h^1 on a bare trace of n elements of [0, 1]: all pressure_errors needs of the interface.
ContactInterface interface_of(int n, double jitter = 0) {
  ContactInterface g;
  g.nonmortar_trace = uniform_trace(1.0, n, jitter);
  g.space = end_modified_p1(g.nonmortar_trace);
  return g;
}

// q_h = sum_i c_i psi_i as nodal values on the trace.
InterfaceCurve multiplier_curve(const ContactInterface& g, const Eigen::VectorXd& c) {
  const Eigen::VectorXd nodal = g.space.C.transpose() * c;
  return {g.nonmortar_trace.x, std::vector<double>(nodal.data(), nodal.data() + nodal.size())};
}

// The nodal interpolant in M_h^1: p at the interior nodes (psi_1, psi_{N-1} carry p(x_1), p(x_{N-1})).
InterfaceCurve interpolant(const ContactInterface& g, const std::function<double(double)>& p) {
  Eigen::VectorXd c(g.space.dim());
  for (int i = 0; i < g.space.dim(); ++i) c[i] = p(g.nonmortar_trace.x[g.space.node_of(i)]);
  return multiplier_curve(g, c);
}

// sigma_N of the manufactured solutions, up to a factor: the sloped profile has p'(1) != 0,
// the flat-ends one p'(0) = p'(1) = 0.
double sloped(double x) { return 1.5 + std::cos(1.5 * pi * x); }
double flat_ends(double x) { return 1.5 + std::cos(2 * pi * x); }
}  // namespace

TEST(PressureNorms, projection_reproduces_every_function_of_the_multiplier_space) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coefficient(-1, 1);
  for (int n : {1, 2, 3, 10}) {
    const ContactInterface g = interface_of(n, n > 2 ? 0.3 : 0.0);
    Eigen::VectorXd c(g.space.dim());
    for (int i = 0; i < c.size(); ++i) c[i] = coefficient(rng);
    const InterfaceCurve q = multiplier_curve(g, c);
    const auto q_of_x = [&](double x) { return g.nonmortar_trace.evaluate(q.value, x); };
    const InterfaceCurve projected = l2_projection(g, q_of_x);
    for (std::size_t j = 0; j < q.value.size(); ++j) EXPECT_NEAR(projected.value[j], q.value[j], 1e-13) << "n = " << n;
    EXPECT_NEAR(pressure_errors(g, q, q_of_x).best_l2, 0.0, 1e-13) << "n = " << n;
  }
}

TEST(PressureNorms, projection_residual_is_orthogonal_to_every_psi) {
  const ContactInterface g = interface_of(13, 0.3);
  const auto p = [](double x) { return std::exp(x) * std::sin(5 * x); };
  const InterfaceCurve projected = l2_projection(g, p);
  // (p - Pi_h p, phi_j) by an 8-point rule per element (the residual is smooth on each), then
  // (., psi_i) = sum_j C_ij (., phi_j)
  const InterfaceTrace& t = g.nonmortar_trace;
  const SegmentRule rule = gauss_legendre(8);
  Eigen::VectorXd residual_phi = Eigen::VectorXd::Zero(t.num_nodes());
  for (int e = 0; e < t.num_elements(); ++e) {
    const double h = t.x[e + 1] - t.x[e];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q], x = t.x[e] + s * h;
      const double r = p(x) - ((1 - s) * projected.value[e] + s * projected.value[e + 1]);
      residual_phi[e] += rule.weights[q] * h * (1 - s) * r;
      residual_phi[e + 1] += rule.weights[q] * h * s * r;
    }
  }
  const Eigen::VectorXd residual_psi = g.space.C * residual_phi;
  EXPECT_LT(residual_psi.cwiseAbs().maxCoeff(), 1e-14) << residual_psi.transpose();
}

TEST(PressureNorms, best_approximation_is_never_above_another_element_of_the_space) {
  std::mt19937 rng(3);
  std::normal_distribution<double> kick(0, 1e-3);
  for (const auto& p : {std::function<double(double)>(sloped), std::function<double(double)>(flat_ends)}) {
    const ContactInterface g = interface_of(16, 0.2);
    const PressureErrors nodal = pressure_errors(g, interpolant(g, p), p);
    EXPECT_LE(nodal.best_l2, nodal.l2);
    EXPECT_GT(nodal.l2, 1.01 * nodal.best_l2);  // the interpolant is not the projection
    // the projection itself, and small moves away from it in every direction
    const InterfaceCurve projected = l2_projection(g, p);
    const PressureErrors itself = pressure_errors(g, projected, p);
    EXPECT_NEAR(itself.l2, itself.best_l2, 1e-14);
    EXPECT_NEAR(itself.hminus, itself.best_hminus, 1e-14);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd c(g.space.dim());
      for (int i = 0; i < c.size(); ++i) c[i] = projected.value[g.space.node_of(i)] + kick(rng);
      EXPECT_LE(itself.best_l2, pressure_errors(g, multiplier_curve(g, c), p).l2);
    }
  }
}

TEST(PressureNorms, norms_split_into_interior_and_end_elements) {
  const ContactInterface g = interface_of(9, 0.3);
  const PressureErrors e = pressure_errors(g, interpolant(g, sloped), sloped);
  EXPECT_NEAR(e.l2 * e.l2, e.l2_interior * e.l2_interior + e.l2_ends * e.l2_ends, 1e-15);
  EXPECT_GT(e.l2_interior, 0.0);
  EXPECT_GT(e.l2_ends, 0.0);
  // the mesh-dependent norm weighs each element by its length: between min h and max h times L2
  const InterfaceTrace& t = g.nonmortar_trace;
  double h_min = 1, h_max = 0;
  for (int k = 0; k < t.num_elements(); ++k) {
    h_min = std::min(h_min, t.x[k + 1] - t.x[k]);
    h_max = std::max(h_max, t.x[k + 1] - t.x[k]);
  }
  EXPECT_GE(e.hminus, std::sqrt(h_min) * e.l2);
  EXPECT_LE(e.hminus, std::sqrt(h_max) * e.l2);
  // on a uniform trace it is sqrt(h) times L2, exactly; and the norms of p = 2 are known
  const ContactInterface u = interface_of(8);
  const PressureErrors c = pressure_errors(u, InterfaceCurve{u.nonmortar_trace.x, std::vector<double>(9, 0.0)},
                                           [](double) { return 2.0; });
  EXPECT_NEAR(c.norm_l2, 2.0, 1e-14);
  EXPECT_NEAR(c.hminus, 2.0 * std::sqrt(1.0 / 8), 1e-14);
  EXPECT_NEAR(c.norm_hminus, 2.0, 1e-14);  // |Gamma_c|^{1/2} ||p||: the same on every mesh
  EXPECT_NEAR(c.l2, 2.0, 1e-14);
  EXPECT_NEAR(c.l2_ends, 2.0 * std::sqrt(2.0 / 8), 1e-14);
  EXPECT_NEAR(c.best_l2, 0.0, 1e-14);  // constants are in M_h^1
}

TEST(PressureNorms, a_kink_inside_an_element_is_integrated_accurately) {
  // p = (x* - x)_+ with x* inside an element: int_0^1 p^2 = x*^3 / 3
  const double x_star = 0.5 + std::sqrt(2.0) / 10;
  const ContactInterface g = interface_of(10);
  const PressureErrors e = pressure_errors(g, InterfaceCurve{g.nonmortar_trace.x, std::vector<double>(11, 0.0)},
                                           [&](double x) { return std::max(0.0, x_star - x); });
  EXPECT_NEAR(e.norm_l2, std::sqrt(x_star * x_star * x_star / 3), 1e-6 * e.norm_l2);
}

// Best approximation in M_h^1 of a smooth p on uniform traces, fitted slopes with a band of
// +-0.1 (printed when they leave it). The end elements hold constants: where p' != 0 at an end
// the L2 error there is about |p'| h^{3/2} / sqrt(12), and the projection, being global, passes
// that defect on to the neighbouring elements (damped by 2 - sqrt(3) per element), so the
// interior without the two end elements falls like h^{3/2} too. With p' = 0 at both ends the
// end elements give h^{5/2} and the whole error is the interior's h^2; the end elements'
// share fades like h^{1/2}, so the local rates come down from 2.45 (16 elements) to 2.03
// (2048), and the fit starts at 512 elements.
namespace {
std::vector<PressureErrors> best_errors(const std::function<double(double)>& p, int n_first, int n_last,
                                        std::vector<double>& h) {
  std::vector<PressureErrors> errors;
  h.clear();
  for (int n = n_first; n <= n_last; n *= 2) {
    const ContactInterface g = interface_of(n);
    h.push_back(1.0 / n);
    errors.push_back(pressure_errors(g, InterfaceCurve{g.nonmortar_trace.x, std::vector<double>(n + 1, 0.0)}, p));
  }
  return errors;
}

std::vector<double> pick(const std::vector<PressureErrors>& errors, double PressureErrors::*member) {
  std::vector<double> v;
  for (const PressureErrors& e : errors) v.push_back(e.*member);
  return v;
}
}  // namespace

TEST(PressureNorms, best_l2_rate_is_three_halves_when_the_pressure_has_a_slope_at_an_end) {
  std::vector<double> h;
  const auto e = best_errors(sloped, 16, 256, h);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_l2)), 1.5, 0.1);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_l2_interior)), 1.5, 0.1);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_hminus)), 2.0, 0.1);
}

TEST(PressureNorms, best_l2_rate_is_two_when_the_pressure_is_flat_at_both_ends) {
  std::vector<double> h;
  const auto e = best_errors(flat_ends, 512, 4096, h);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_l2)), 2.0, 0.1);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_l2_interior)), 2.0, 0.1);
  EXPECT_NEAR(log_log_slope(h, pick(e, &PressureErrors::best_hminus)), 2.5, 0.1);
}

TEST(PressureNorms, a_curve_that_does_not_span_the_trace_is_refused) {
  const ContactInterface g = interface_of(4);
  EXPECT_THROW(pressure_errors(g, InterfaceCurve{{0.0, 0.5}, {1.0, 1.0}}, sloped), std::invalid_argument);
  EXPECT_THROW(pressure_errors(g, InterfaceCurve{{0.0, 1.0}, {1.0}}, sloped), std::invalid_argument);
  EXPECT_THROW(pressure_errors(g, InterfaceCurve{{0.0, 0.6, 0.4, 1.0}, {1, 1, 1, 1}}, sloped), std::invalid_argument);
}

// A pressure scales with E, and E may be given in any unit: every norm of pressure_errors must
// scale with the pressure, also where its square would overflow (1e300) or underflow (1e-160).
TEST(PressureNorms, every_norm_scales_with_the_pressure_from_1e_minus300_to_1e300) {
  const ContactInterface g = interface_of(7, 0.3);
  const InterfaceCurve unit_h = interpolant(g, sloped);
  const PressureErrors unit = pressure_errors(g, unit_h, sloped);
  ASSERT_GT(unit.l2, 0.0);
  for (double scale : {1e-300, 1e-160, 1e160, 1e300}) {
    InterfaceCurve p_h = unit_h;
    for (double& v : p_h.value) v *= scale;
    const PressureErrors e = pressure_errors(g, p_h, [&](double x) { return scale * sloped(x); });
    for (double PressureErrors::*member :
         {&PressureErrors::l2, &PressureErrors::l2_interior, &PressureErrors::l2_ends, &PressureErrors::hminus,
          &PressureErrors::best_l2, &PressureErrors::best_l2_interior, &PressureErrors::best_hminus,
          &PressureErrors::norm_l2, &PressureErrors::norm_hminus})
      // the same arithmetic up to rounding and the projection's solve: 1e-12 relative
      EXPECT_NEAR(e.*member / scale, unit.*member, 1e-12 * unit.*member) << "scale " << scale;
  }
}

// Values by hand: p(x) = x on four elements of [0, 1], p_h its interpolant in M_h^1 (exact on the
// interior elements, the constants 1/4 and 3/4 on the end ones). The error lives on the end
// elements: int_0^{1/4} (x - 1/4)^2 = 1/192 on each, so L2 = (1/96)^{1/2} and the
// mesh-dependent norm (h / 96)^{1/2}.
TEST(PressureNorms, interpolant_of_a_linear_pressure_has_the_norms_computed_by_hand) {
  const ContactInterface g = interface_of(4);
  const auto p = [](double x) { return x; };
  const PressureErrors e = pressure_errors(g, interpolant(g, p), p);
  EXPECT_NEAR(e.l2, std::sqrt(1.0 / 96), 1e-14);
  EXPECT_NEAR(e.l2_ends, std::sqrt(1.0 / 96), 1e-14);
  EXPECT_NEAR(e.l2_interior, 0.0, 1e-14);
  EXPECT_NEAR(e.hminus, std::sqrt(0.25 / 96), 1e-14);
  EXPECT_NEAR(e.norm_l2, std::sqrt(1.0 / 3), 1e-14);
  EXPECT_LE(e.best_l2, e.l2);
}

// The edge of a contact zone: p(x) = sqrt(1 - ((x - x0)/a)^2) on |x - x0| < a, 0 outside (Hertz's
// shape), with both edges inside elements, against its best approximation in M_h^1 computed in
// closed form (hertz_best_approximation.hpp). A rule that does not cut at the edges integrates
// a square root across them and is off in the fourth digit.
TEST(PressureNorms, best_approximation_of_a_square_root_edge_matches_its_closed_form) {
  const double x0 = 0.5, a = std::sqrt(2.0) / 6;  // edges 0.264 and 0.736, never nodes
  const auto p = [&](double x) { return std::fabs(x - x0) < a ? std::sqrt(1 - std::pow((x - x0) / a, 2)) : 0.0; };
  for (int n : {10, 40, 160}) {
    const ContactInterface g = interface_of(n);
    const double norm = std::sqrt(4 * a / 3), best = norm * hertz_best::relative_best_error(1.0, n, x0, a);
    const InterfaceCurve zero{g.nonmortar_trace.x, std::vector<double>(n + 1, 0.0)};
    const PressureErrors cut = pressure_errors(g, zero, p, {x0 - a, x0 + a});
    EXPECT_NEAR(cut.norm_l2, norm, 1e-12) << n;
    EXPECT_NEAR(cut.l2, norm, 1e-12) << n;  // the error of the zero curve is p itself
    EXPECT_NEAR(cut.best_l2, best, 1e-9 * best) << n;
    // without the edges the same rule misstates the best error, far beyond these tolerances
    const PressureErrors uncut = pressure_errors(g, zero, p);
    EXPECT_GT(std::fabs(uncut.best_l2 - best), 1e-6 * best) << n;
  }
}
