// The interface layer for traces of degree q = 2 (P2 bodies, chapter 7): the Gauss rule of the
// mortar matrices, M_h^1 = continuous P2 with P1 on the end elements, D and M, pointwise rows,
// and the curves of degree 2 (jump, pressure, L2 error). Every expected value is computed here
// independently: psi_i through C and InterfaceTrace::evaluate, integrals by a composite Gauss
// rule cut at the breakpoints of both traces.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/fem/quadrature.hpp"
#include "common/interface/mortar_matrices.hpp"
#include "common/interface/multiplier_space.hpp"
#include "common/contact/pressure_norms.hpp"

using namespace mortar;

namespace {
using Fn = std::function<double(double)>;

// A jittered trace of degree q on [0, 1].
InterfaceTrace trace(int n, unsigned seed, int degree) { return uniform_trace(1.0, n, 0.3, seed, degree); }

// psi_i(x) = sum_j C(i, j) phi_j(x), read through the trace's own evaluation.
double psi(const MultiplierSpace& space, const InterfaceTrace& t, int i, double x) {
  std::vector<double> row(static_cast<std::size_t>(t.num_dofs()), 0.0);
  for (RowMajorMatrix::InnerIterator it(space.C, i); it; ++it) row[it.col()] = it.value();
  return t.evaluate(row, x);
}

// phi_k of a trace at x (the function of nodal values e_k).
double phi(const InterfaceTrace& t, int k, double x) {
  std::vector<double> unit(static_cast<std::size_t>(t.num_dofs()), 0.0);
  unit[k] = 1.0;
  return t.evaluate(unit, x);
}

// int_0^L f by 4 pieces x 5-point Gauss between consecutive cuts (the element ends of all the
// given traces): exact to round-off for a piecewise polynomial of degree 9 or less on the cuts.
double integrate(const Fn& f, const std::vector<const InterfaceTrace*>& traces) {
  std::vector<double> cuts;
  for (const InterfaceTrace* t : traces) cuts.insert(cuts.end(), t->x.begin(), t->x.end());
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const SegmentRule rule = gauss_legendre(5);
  double sum = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
    for (int piece = 0; piece < 4; ++piece) {
      const double h = (cuts[c + 1] - cuts[c]) / 4, a = cuts[c] + piece * h;
      for (std::size_t q = 0; q < rule.points.size(); ++q) sum += rule.weights[q] * h * f(a + rule.points[q] * h);
    }
  return sum;
}

// Nodal values of f on the trace nodes.
Eigen::VectorXd sample(const InterfaceTrace& t, const Fn& f) {
  Eigen::VectorXd v(t.num_dofs());
  for (int j = 0; j < t.num_dofs(); ++j) v[j] = f(t.node_x(j));
  return v;
}

// Points spread over Gamma_c = [0, 1], element ends and midpoints included.
std::vector<double> points() {
  std::vector<double> x;
  for (int k = 0; k <= 200; ++k) x.push_back(k / 200.0);
  return x;
}

double max_abs(const Eigen::MatrixXd& a) { return a.cwiseAbs().maxCoeff(); }
}  // namespace

// The mortar products psi_i phi_j have degree 2q on a merged segment: q + 1 Gauss points, of
// degree 2q + 1, are exact for them. For q = 2, 3 points: degree 5 >= 4 (x^6 is missed); for
// q = 1, 2 points: degree 3 >= 2 (x^4 is missed).
TEST(P2Interface, mortar_gauss_rule_has_degree_2q_plus_1) {
  for (const int q : {1, 2}) {
    const int n = mortar_gauss_points(q, q);
    EXPECT_EQ(n, q + 1);
    const SegmentRule rule = gauss_legendre(n);
    const auto integral = [&](int k) {
      double s = 0;
      for (std::size_t p = 0; p < rule.points.size(); ++p) s += rule.weights[p] * std::pow(rule.points[p], k);
      return s;
    };
    const int degree = 2 * q + 1;
    for (int k = 0; k <= degree; ++k) EXPECT_NEAR(integral(k), 1.0 / (k + 1), 1e-15) << "q = " << q << ", x^" << k;
    EXPECT_GT(std::fabs(integral(degree + 1) - 1.0 / (degree + 2)), 1e-5) << "q = " << q;
    EXPECT_GE(degree, 2 * q);  // the degree of the products psi_i phi_j
  }
  EXPECT_EQ(mortar_gauss_points(1, 2), 3);  // a P1 trace against a P2 one needs the P2 rule
  EXPECT_EQ(mortar_gauss_points(2, 1), 3);
}

// M_h^1 for q = 2 has dimension 2N - 1, a partition of unity, P1 on the two end elements, and
// is the nodal basis (psi_i = 1 at its node, 0 at the others) of {continuous P2, P1 at the
// ends}: it reproduces every such function, and the L2 projection onto it leaves them unchanged.
TEST(P2Interface, end_modified_p2_is_continuous_p2_and_linear_on_the_end_elements) {
  for (const int N : {2, 3, 7}) {
    const InterfaceTrace t = trace(N, 4 + N, 2);
    const MultiplierSpace space = end_modified_p2(t);
    ASSERT_EQ(space.dim(), 2 * N - 1) << "N = " << N;
    ASSERT_EQ(space.C.cols(), 2 * N + 1);
    for (const double x : points()) {
      double sum = 0;
      for (int i = 0; i < space.dim(); ++i) sum += psi(space, t, i, x);
      EXPECT_NEAR(sum, 1.0, 1e-14) << "N = " << N << ", x = " << x;
    }
    for (int i = 0; i < space.dim(); ++i)
      for (const int e : {0, N - 1}) {
        const double a = t.x[e], b = t.x[e + 1];
        EXPECT_NEAR(psi(space, t, i, 0.5 * (a + b)), 0.5 * (psi(space, t, i, a) + psi(space, t, i, b)), 1e-15)
            << "N = " << N << ", psi_" << i << " on element " << e;
      }
    // the nodes of M_h: every trace node but the end-element midpoints 1 and 2N - 1, in order
    std::vector<int> node;
    for (int j = 0; j <= 2 * N; ++j)
      if (j != 1 && j != 2 * N - 1) node.push_back(j);
    for (int i = 0; i < space.dim(); ++i)
      for (int k = 0; k < space.dim(); ++k)
        EXPECT_NEAR(psi(space, t, i, t.node_x(node[k])), i == k ? 1.0 : 0.0, 1e-15) << "psi_" << i << " at node " << node[k];
    // g: the quadratic f on the interior elements, its linear interpolant on the two end ones
    const auto f = [](double x) { return 0.7 - 2.3 * x + 4.1 * x * x; };
    const auto g = [&](double x) {
      const int e = t.element_containing(x);
      if (e != 0 && e != N - 1) return f(x);
      const double s = (x - t.x[e]) / (t.x[e + 1] - t.x[e]);
      return (1 - s) * f(t.x[e]) + s * f(t.x[e + 1]);
    };
    for (const double x : points()) {
      double v = 0;
      for (int i = 0; i < space.dim(); ++i) v += g(t.node_x(node[i])) * psi(space, t, i, x);
      EXPECT_NEAR(v, g(x), 1e-14) << "N = " << N << ", x = " << x;
    }
    ContactInterface gamma;
    gamma.nonmortar_trace = t;
    gamma.space = space;
    const InterfaceCurve projected = l2_projection(gamma, g);
    ASSERT_EQ(projected.degree, 2);
    for (int j = 0; j < t.num_dofs(); ++j) EXPECT_NEAR(projected.value[j], g(t.node_x(j)), 1e-13) << "node " << j;
  }
}

// Each builder takes only the trace it is made for: P2 needs 2 elements (the two end elements
// must differ), and neither builds on the other degree.
TEST(P2Interface, end_modified_spaces_refuse_the_wrong_trace) {
  EXPECT_THROW(end_modified_p2(trace(1, 1, 2)), std::invalid_argument);
  EXPECT_THROW(end_modified_p2(trace(5, 1, 1)), std::invalid_argument);
  EXPECT_THROW(end_modified_p1(trace(5, 1, 2)), std::invalid_argument);
  EXPECT_EQ(end_modified_space(trace(5, 1, 2)).dim(), 9);
  EXPECT_EQ(end_modified_space(trace(5, 1, 1)).dim(), 4);
}

// D and M for q = 2 on nonmatching jittered traces, either trace the non-mortar one:
// (a) D 1 = M 1 = (int psi_i)_i; (b) D u1 and M u2 are int psi_i u for u quadratic (sampled
// at the nodes) and for a general P2 function u2 on trace 2, against an independent quadrature.
TEST(P2Interface, mortar_matrices_integrate_psi_against_p2_traces_exactly) {
  const int pairs[][2] = {{7, 5}, {5, 7}, {4, 9}, {9, 4}};
  for (const auto& [N1, N2] : pairs) {
    const InterfaceTrace t1 = trace(N1, 3, 2), t2 = trace(N2, 11, 2);
    const MultiplierSpace space = end_modified_p2(t1);
    const MortarMatrices m = mortar_matrices(t1, t2, merge_traces(t1, t2), space);
    ASSERT_EQ(m.D.rows(), 2 * N1 - 1);
    ASSERT_EQ(m.D.cols(), 2 * N1 + 1);
    ASSERT_EQ(m.M.cols(), 2 * N2 + 1);
    const Eigen::VectorXd psi_int = integrals_against_basis(space, t1, [](double) { return 1.0; });
    const double scale = psi_int.cwiseAbs().maxCoeff();
    EXPECT_LT(max_abs(m.D * Eigen::VectorXd::Ones(t1.num_dofs()) - psi_int), 1e-14 * scale) << N1 << "/" << N2;
    EXPECT_LT(max_abs(m.M * Eigen::VectorXd::Ones(t2.num_dofs()) - psi_int), 1e-14 * scale) << N1 << "/" << N2;

    const Fn u1 = [](double x) { return 0.4 + 1.3 * x - 2.9 * x * x; };
    const Fn u2 = [](double x) { return -1.1 + 0.5 * x + 3.7 * x * x; };
    Eigen::VectorXd w(t2.num_dofs());  // a P2 function on trace 2, no polynomial on Gamma_c
    for (int k = 0; k < w.size(); ++k) w[k] = std::cos(7.0 * k);
    const std::vector<double> wv(w.data(), w.data() + w.size());
    const Eigen::VectorXd Du1 = m.D * sample(t1, u1), Mu2 = m.M * sample(t2, u2), Mw = m.M * w;
    for (int i = 0; i < space.dim(); ++i) {
      EXPECT_NEAR(psi_int[i], integrate([&](double x) { return psi(space, t1, i, x); }, {&t1}), 1e-15);
      const auto against = [&](const Fn& u) { return [&, u](double x) { return psi(space, t1, i, x) * u(x); }; };
      EXPECT_NEAR(Du1[i], integrate(against(u1), {&t1}), 1e-14) << N1 << "/" << N2 << ", row " << i;
      EXPECT_NEAR(Mu2[i], integrate(against(u2), {&t1}), 1e-14) << N1 << "/" << N2 << ", row " << i;
      EXPECT_NEAR(Mw[i], integrate(against([&](double x) { return t2.evaluate(wv, x); }), {&t1, &t2}), 1e-14)
          << N1 << "/" << N2 << ", row " << i;
    }
  }
}

// (c) On matching traces (same nodes, same degree) the mortar side is the non-mortar one: D = M.
TEST(P2Interface, matching_p2_traces_give_D_equal_to_M) {
  const InterfaceTrace t = trace(6, 8, 2);
  const MortarMatrices m = mortar_matrices(t, t, merge_traces(t, t), end_modified_p2(t));
  EXPECT_LT(max_abs(Eigen::MatrixXd(m.D - m.M)), 1e-16);
  EXPECT_GT(max_abs(Eigen::MatrixXd(m.D)), 0.01);
}

// P1 is unchanged: every entry of D and M on jittered P1 traces is int psi_i phi^1_j and
// int psi_i phi^2_k, by the independent quadrature.
TEST(P2Interface, p1_mortar_matrices_are_the_direct_integrals) {
  const InterfaceTrace t1 = trace(6, 2, 1), t2 = trace(9, 7, 1);
  const MultiplierSpace space = end_modified_p1(t1);
  const MortarMatrices m = mortar_matrices(t1, t2, merge_traces(t1, t2), space);
  const Eigen::MatrixXd D(m.D), M(m.M);
  ASSERT_EQ(D.rows(), 5);
  for (int i = 0; i < space.dim(); ++i) {
    for (int j = 0; j < t1.num_dofs(); ++j)
      EXPECT_NEAR(D(i, j), integrate([&](double x) { return psi(space, t1, i, x) * phi(t1, j, x); }, {&t1}), 1e-15);
    for (int k = 0; k < t2.num_dofs(); ++k)
      EXPECT_NEAR(M(i, k), integrate([&](double x) { return psi(space, t1, i, x) * phi(t2, k, x); }, {&t1, &t2}), 1e-15);
  }
}

// Pointwise matching for q = 2: one row per node of the P2 non-mortar trace (2 N1 + 1, the
// midpoints included), identity on the non-mortar side, and on the mortar side the P2
// interpolation at node_x(a): coefficients summing to 1 that reproduce a quadratic.
TEST(P2Interface, pointwise_rows_interpolate_the_p2_mortar_trace_at_every_node) {
  ContactInterface gamma;
  gamma.nonmortar_trace = trace(7, 3, 2);
  gamma.mortar_trace = trace(5, 9, 2);
  const MatchingRows rows = pointwise_matching_rows(gamma);
  ASSERT_EQ(rows.nonmortar.rows(), 15);
  ASSERT_EQ(rows.mortar.cols(), 11);
  EXPECT_LT(max_abs(Eigen::MatrixXd(rows.nonmortar) - Eigen::MatrixXd::Identity(15, 15)), 1e-16);
  const Fn f = [](double x) { return 0.9 - 3.1 * x + 2.6 * x * x; };
  const Eigen::VectorXd sums = rows.mortar * Eigen::VectorXd::Ones(11), values = rows.mortar * sample(gamma.mortar_trace, f);
  for (int a = 0; a < 15; ++a) {
    EXPECT_NEAR(sums[a], 1.0, 1e-15) << "row " << a;
    EXPECT_NEAR(values[a], f(gamma.nonmortar_trace.node_x(a)), 1e-14) << "row " << a;
  }
}

// A curve of degree 2 is the piecewise quadratic through its points: zero L2 error against
// the quadratic it samples; against a cubic c = kappa x^3 + ..., whose interpolation error on
// a piece of length h is kappa (x - a)(x - m)(x - b), the error is kappa (sum h^7 / 840)^{1/2}.
TEST(P2Interface, degree_2_curves_and_their_l2_error) {
  const InterfaceTrace t = trace(6, 5, 2);
  const Fn quadratic = [](double x) { return 1.2 - 0.8 * x + 2.5 * x * x; };
  const double kappa = 3.0;
  const Fn cubic = [&](double x) { return quadratic(x) + kappa * x * x * x; };
  InterfaceCurve q{{}, {}, 2}, c{{}, {}, 2};
  for (int j = 0; j < t.num_dofs(); ++j) {
    const double x = t.node_x(j);
    q.x.push_back(x);
    q.value.push_back(quadratic(x));
    c.x.push_back(x);
    c.value.push_back(cubic(x));
  }
  ASSERT_EQ(q.pieces(), 6);
  EXPECT_LT(l2_error(q, quadratic), 1e-15);
  double sum = 0;
  for (int e = 0; e < t.num_elements(); ++e) sum += std::pow(t.x[e + 1] - t.x[e], 7) / 840;
  const double expected = kappa * std::sqrt(sum);
  EXPECT_NEAR(l2_error(c, cubic), expected, 1e-12 * expected);
  EXPECT_NEAR(l2_error(q, cubic), kappa / std::sqrt(7.0), 1e-14);  // ||kappa x^3||_{L2(0, 1)}
}

// On two P2 bodies: the same quadratic u_y on both sides of Gamma_c gives a zero jump; u_y
// differing by a quadratic g gives a degree-2 jump curve equal to g everywhere (both non-mortar
// choices). The integral-matching pressure of multipliers sampled from a linear p is p, and the
// pointwise pressure of the nodal forces p(a) int phi_a is p at every node.
TEST(P2Interface, jump_and_pressure_on_two_p2_bodies) {
  TwoBodyGeometry geometry;
  geometry.n1 = 5;
  geometry.m1 = 2;
  geometry.n2 = 7;
  geometry.m2 = 2;
  geometry.jitter = 0.3;
  geometry.degree = 2;
  const TwoBodies bodies = make_two_bodies(geometry, Material(1, 0.3), Material(1, 0.3));
  const Fn f = [](double x) { return 0.3 + 1.9 * x - 1.4 * x * x;};
  const Fn g = [](double x) { return -0.2 + 0.6 * x + 2.2 * x * x; };
  const auto displacement = [&](const Fn& body2_extra) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(bodies.num_dofs());
    for (int l = 0; l < 2; ++l)
      for (int a = 0; a < bodies.body(l).mesh.num_nodes(); ++a) {
        const double x = bodies.body(l).mesh.nodes[a].x();
        u[bodies.dof(l, a, 0)] = 0.5 * x;  // tangential: no part of the jump
        u[bodies.dof(l, a, 1)] = f(x) + (l == 1 ? body2_extra(x) : 0.0);
      }
    return u;
  };
  for (const int nonmortar : {0, 1}) {
    const ContactInterface gamma = make_interface(bodies, nonmortar);
    ASSERT_EQ(gamma.nonmortar_trace.degree, 2);
    const InterfaceCurve zero = normal_jump(bodies, gamma, displacement([](double) { return 0.0; }));
    ASSERT_EQ(zero.degree, 2);
    ASSERT_EQ(zero.x.size(), 2 * gamma.grid.breakpoints.size() - 1);
    for (const double v : zero.value) EXPECT_NEAR(v, 0.0, 1e-14);
    const InterfaceCurve jump = normal_jump(bodies, gamma, displacement(g));
    for (std::size_t k = 0; k < jump.x.size(); ++k) EXPECT_NEAR(jump.value[k], g(jump.x[k]), 1e-14);
    for (int e = 0; e < jump.pieces(); ++e)
      for (const double s : {0.1, 0.37, 0.8}) {
        const double x = jump.x[2 * e] + s * (jump.x[2 * e + 2] - jump.x[2 * e]);
        EXPECT_NEAR(jump.at(e, s), g(x), 1e-14) << "piece " << e << ", s = " << s;
      }
    EXPECT_LT(l2_error(jump, g), 1e-14);

    const std::vector<bool> free(static_cast<std::size_t>(bodies.num_dofs()), false);
    const InterfaceTrace& t = gamma.nonmortar_trace;
    const int N = t.num_elements();
    const Fn p = [](double x) { return 2.0 + 0.7 * x; };
    // integral: lambda_i = p at the node of psi_i (every node but the end-element midpoints)
    const Constraints ci = build_constraints(bodies, gamma, Matching::integral, free);
    ASSERT_EQ(ci.B.rows(), 2 * N - 1);
    Eigen::VectorXd lambda(ci.B.rows());
    for (int i = 0; i < lambda.size(); ++i) lambda[i] = p(t.node_x(i == 0 ? 0 : i == 2 * N - 2 ? 2 * N : i + 1));
    const InterfaceCurve pi = contact_pressure(gamma, ci, lambda);
    ASSERT_EQ(pi.degree, 2);
    for (int j = 0; j < t.num_dofs(); ++j) EXPECT_NEAR(pi.value[j], p(pi.x[j]), 1e-14) << "node " << j;
    EXPECT_NEAR(total_contact_force(gamma, ci, lambda), 2.35, 1e-14);  // int_0^1 p
    // pointwise: 2N + 1 rows, nodal forces p(a) int phi_a (h/6 at the ends, 2h/3 at midpoints)
    const Constraints cp = build_constraints(bodies, gamma, Matching::pointwise, free);
    ASSERT_EQ(cp.B.rows(), 2 * N + 1);
    Eigen::VectorXd force(cp.B.rows());
    for (int a = 0; a < force.size(); ++a) {
      const int e = std::min(a / 2, N - 1);
      const double h = t.x[e + 1] - t.x[e], hl = a >= 2 && a % 2 == 0 ? t.x[e] - t.x[e - 1] : 0.0;
      const double weight = a % 2 == 1 ? 2 * h / 3 : a == 2 * N ? h / 6 : (h + hl) / 6;
      force[a] = p(t.node_x(a)) * weight;
    }
    const InterfaceCurve pp = contact_pressure(gamma, cp, force);
    for (int j = 0; j < t.num_dofs(); ++j) EXPECT_NEAR(pp.value[j], p(pp.x[j]), 1e-13) << "node " << j;
  }
}

// Where the L2 projection onto M_h^1 (q = 2) loses its order, on chapter 4's pressure
// p = 1.5 + cos(3 pi x / 2) and uniform traces of 12 to 768 elements (chapter 7's notes, "The
// pressure"). Its error is measured on parts of Gamma_c: all but the two P1 end elements
// (h^{5/2}: the end defect reaches inward, decaying element by element), the middle half (h^3,
// what P2 can do), and, for comparison, the projection onto all of P2 (h^3 without the end
// elements). The rates are printed as the notes' table, and the finest errors pinned.
TEST(P2Interface, the_projection_onto_m_h_loses_half_an_order_near_the_ends_only) {
  const Fn p = [](double x) { return 1.5 + std::cos(1.5 * M_PI * x); };
  const SegmentRule g = gauss_legendre(6);
  // the L2 error of a curve of nodal values on the elements [first, last) of t
  const auto error_on = [&](const InterfaceTrace& t, const std::vector<double>& v, int first, int last) {
    double sum = 0;
    for (int e = first; e < last; ++e) {
      const double a = t.x[e], h = t.x[e + 1] - t.x[e];
      for (std::size_t k = 0; k < g.points.size(); ++k) {
        const double x = a + h * g.points[k], d = p(x) - t.evaluate(v, x);
        sum += g.weights[k] * h * d * d;
      }
    }
    return std::sqrt(sum);
  };
  const char* parts[] = {"M_h^1, all but the end elements", "M_h^1, all but three elements at each end",
                         "M_h^1, the middle half [L/4, 3L/4]", "all of P2, all but the end elements"};
  std::vector<std::array<double, 4>> errors;
  for (int n = 12; n <= 768; n *= 2) {
    ContactInterface gamma;
    gamma.nonmortar_trace = uniform_trace(1.0, n, 0.0, 1, 2);
    gamma.space = end_modified_p2(gamma.nonmortar_trace);
    const std::vector<double> m_h = l2_projection(gamma, p).value;
    gamma.space.C = RowMajorMatrix(gamma.nonmortar_trace.num_dofs(), gamma.nonmortar_trace.num_dofs());
    gamma.space.C.setIdentity();
    const std::vector<double> p2 = l2_projection(gamma, p).value;
    const InterfaceTrace& t = gamma.nonmortar_trace;
    errors.push_back({error_on(t, m_h, 1, n - 1), error_on(t, m_h, 3, n - 3), error_on(t, m_h, n / 4, 3 * n / 4),
                      error_on(t, p2, 1, n - 1)});
  }
  for (int part = 0; part < 4; ++part) {
    std::printf("%-45s", parts[part]);
    std::vector<double> rates;
    for (std::size_t l = 1; l < errors.size(); ++l) rates.push_back(std::log2(errors[l - 1][part] / errors[l][part]));
    for (double r : rates) std::printf(" %.2f", r);
    std::printf("   (finest: %.3e)\n", errors.back()[part]);
    // over the last three steps: 5/2, 3 and 3 settled; three elements from the ends, between
    // the two and drifting back towards 5/2 as the layer of fixed element count shrinks
    const double rate = part == 0 ? 2.5 : part == 1 ? 2.85 : 3.0;
    for (std::size_t k = rates.size() - 3; k < rates.size(); ++k)
      EXPECT_NEAR(rates[k], rate, part == 1 ? 0.1 : 0.02) << parts[part] << ", step " << k + 1;
    // and the finest errors, 768 elements (a rate is blind to a constant factor)
    const double finest[] = {2.643e-08, 1.216e-09, 6.642e-10, 9.379e-10};
    EXPECT_NEAR(errors.back()[part], finest[part], 1e-3 * finest[part]) << parts[part];
  }
}
