#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "exercise.hpp"

namespace {

using exercise::Matrix12;
using exercise::Segment;
using exercise::Vector12;

Vector12 random_vector(unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  Vector12 v;
  for (int i = 0; i < 12; ++i) v(i) = scale * d(rng);
  return v;
}

// A segment of length 0.3 whose jump reads dofs 1 (body 1, minus) and 7 (body 2, plus) at a,
// 3 and 9 at b, as a P1 trace on each side would.
Segment segment(double gamma) {
  Segment s;
  s.a = 0.2;
  s.b = 0.5;
  s.p = random_vector(1, 1.0);
  s.jump_a(1) = -1;
  s.jump_a(7) = 1;
  s.jump_b(3) = -1;
  s.jump_b(9) = 1;
  s.gamma = gamma;
  return s;
}

// The same integrals by brute force: 200,000 midpoints, [P]_+ evaluated pointwise, no cuts.
Vector12 brute_force_residual(const Segment& s, double theta, const std::function<double(double)>& g, const Vector12& u) {
  const int n = 200000;
  const double h = (s.b - s.a) / n, pu = s.p.dot(u);
  Vector12 r = -(theta / s.gamma) * (s.b - s.a) * pu * s.p;
  for (int k = 0; k < n; ++k) {
    const double x = s.a + (k + 0.5) * h, t = (x - s.a) / (s.b - s.a);
    const Vector12 J = (1 - t) * s.jump_a + t * s.jump_b;
    const double P = pu + s.gamma * (J.dot(u) - g(x));
    if (P > 0) r += (h / s.gamma) * P * (theta * s.p + s.gamma * J);
  }
  return r;
}

Matrix12 central_differences(const Segment& s, double theta, const std::function<double(double)>& g, const Vector12& u) {
  Matrix12 J;
  const double eps = 1e-7;
  for (int j = 0; j < 12; ++j) {
    Vector12 up = u, um = u;
    up(j) += eps;
    um(j) -= eps;
    J.col(j) = (exercise::nitsche_segment_term(s, theta, g, up).residual -
                exercise::nitsche_segment_term(s, theta, g, um).residual) / (2 * eps);
  }
  return J;
}

// u with [u.n] = 0.02 at a and 0.01 at b, and p(u) = 0.003
Vector12 pressed(const Segment& s) {
  Vector12 u = random_vector(2, 0.01);
  u(1) = 0;
  u(7) = 0.02;
  u(3) = 0;
  u(9) = 0.01;
  // shift the dofs p reads least to set p(u) = 0.003 exactly
  int k = 0;
  for (int i = 0; i < 12; ++i)
    if (i != 1 && i != 3 && i != 7 && i != 9 && std::fabs(s.p(i)) > std::fabs(s.p(k))) k = i;
  u(k) += (0.003 - s.p.dot(u)) / s.p(k);
  return u;
}

}  // namespace

// Open everywhere (g far above the jump): only -(theta / gamma) int p(u) p(v) is left.
TEST(NitscheSegmentTerm, an_open_segment_keeps_only_the_consistency_term) {
  const Segment s = segment(20);
  const Vector12 u = pressed(s);
  for (double theta : {1.0, 0.0, -1.0}) {
    const auto t = exercise::nitsche_segment_term(s, theta, [](double) { return 1.0; }, u);
    const Vector12 r = -(theta / 20) * 0.3 * s.p.dot(u) * s.p;
    EXPECT_LT((t.residual - r).lpNorm<Eigen::Infinity>(), 1e-15) << "theta " << theta;
    EXPECT_LT((t.jacobian + (theta / 20) * 0.3 * s.p * s.p.transpose()).lpNorm<Eigen::Infinity>(), 1e-15);
  }
}

// In contact everywhere (g = 0 below a positive jump): P is linear, the integrand quadratic, and
// Simpson's rule is exact. Worked by hand: with p(u) = 0.003 and gamma = 20, P = 0.003 + 20 [u.n]
// is 0.403 at a and 0.203 at b.
TEST(NitscheSegmentTerm, a_closed_segment_is_integrated_exactly) {
  const Segment s = segment(20);
  const Vector12 u = pressed(s);
  const double theta = 1;
  const auto P = [&](double x) {
    const double t = (x - s.a) / 0.3;
    return 0.003 + 20 * ((1 - t) * 0.02 + t * 0.01);
  };
  EXPECT_NEAR(P(s.a), 0.403, 1e-15);
  EXPECT_NEAR(P(s.b), 0.203, 1e-15);
  Vector12 r = -(theta / 20) * 0.3 * 0.003 * s.p;
  const double xs[3] = {s.a, 0.5 * (s.a + s.b), s.b}, ws[3] = {0.05, 0.2, 0.05};  // Simpson, L = 0.3
  for (int q = 0; q < 3; ++q) {
    const double t = (xs[q] - s.a) / 0.3;
    r += (ws[q] / 20) * P(xs[q]) * (theta * s.p + 20 * ((1 - t) * s.jump_a + t * s.jump_b));
  }
  const auto term = exercise::nitsche_segment_term(s, theta, [](double) { return 0.0; }, u);
  EXPECT_LT((term.residual - r).lpNorm<Eigen::Infinity>(), 1e-14 * r.lpNorm<Eigen::Infinity>());
}

// A cubic gap that crosses the jump once inside the segment, and one that opens a gap in the
// middle (two roots): the kinks must be found, not guessed from a quadratic, to match the brute
// force to 1e-9. The Newton matrix is the residual's derivative, symmetric only for theta = 1.
TEST(NitscheSegmentTerm, kinks_inside_the_segment_are_integrated_exactly) {
  const Segment s = segment(20);
  const Vector12 u = pressed(s);
  const std::function<double(double)> one_root = [](double x) { return 0.015 + 40 * std::pow(x - 0.33, 3); };
  const std::function<double(double)> two_roots = [](double x) {
    return 0.02 - std::pow(x - 0.35, 2) + std::pow(x - 0.35, 3);
  };
  const std::function<double(double)>* gaps[2] = {&one_root, &two_roots};
  for (int roots = 1; roots <= 2; ++roots) {
    const std::function<double(double)>& g = *gaps[roots - 1];
    int sign_changes = 0;
    const auto P = [&](double x) {
      const double t = (x - s.a) / 0.3;
      return 0.003 + 20 * ((1 - t) * 0.02 + t * 0.01 - g(x));
    };
    for (int k = 0; k < 300; ++k) sign_changes += (P(s.a + k * 0.001) > 0) != (P(s.a + (k + 1) * 0.001) > 0);
    ASSERT_EQ(sign_changes, roots);
    for (double theta : {1.0, 0.0, -1.0}) {
      const auto term = exercise::nitsche_segment_term(s, theta, g, u);
      const Vector12 brute = brute_force_residual(s, theta, g, u);
      EXPECT_LT((term.residual - brute).lpNorm<Eigen::Infinity>(), 1e-9 * brute.lpNorm<Eigen::Infinity>())
          << sign_changes << " roots, theta " << theta;
      const Matrix12 fd = central_differences(s, theta, g, u);
      EXPECT_LT((term.jacobian - fd).lpNorm<Eigen::Infinity>(), 1e-6 * fd.lpNorm<Eigen::Infinity>())
          << sign_changes << " roots, theta " << theta;
      const double asymmetry = (term.jacobian - term.jacobian.transpose()).lpNorm<Eigen::Infinity>();
      if (theta == 1) EXPECT_LT(asymmetry, 1e-14 * term.jacobian.lpNorm<Eigen::Infinity>());
      else EXPECT_GT(asymmetry, 1e-3 * term.jacobian.lpNorm<Eigen::Infinity>());
    }
  }
}
