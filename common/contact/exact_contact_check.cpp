#include "common/contact/exact_contact_check.hpp"

#include <algorithm>
#include <cmath>

namespace mortar {

namespace {
// d F / d x_j at p, central differences of order 4 with step s
// (the declared type evaluates the expression: its operands are temporaries)
template <class F>
auto derivative(const F& f, const Eigen::Vector2d& p, int j, double s) -> decltype(f(p)) {
  Eigen::Vector2d e = Eigen::Vector2d::Zero();
  e[j] = s;
  return ((f(p - 2 * e) - f(p + 2 * e)) + 8.0 * (f(p + e) - f(p - e))) / (12 * s);
}

struct Sample {
  int body;
  Eigen::Vector2d p;
  double depth;
};

std::vector<Sample> body_samples(double L, double H1, double H2) {
  std::vector<Sample> s;
  for (int l = 0; l < 2; ++l) {
    const double H = l == 0 ? H1 : H2, sign = l == 0 ? 1 : -1;
    for (double t : {0.002, 0.02, 0.1, 0.3, 0.6, 1.0})
      for (int i = 0; i <= 40; ++i) {
        // abscissae off the midpoint and off simple fractions of L: no sample on a symmetry line
        const double x = L * (0.003 + 0.994 * i / 40.0);
        s.push_back({l, Eigen::Vector2d(x, sign * t * H), t * H});
      }
  }
  return s;
}
}  // namespace

double ExactContactResiduals::worst() const {
  return std::max({gradient, equilibrium, boundary, traction, sign, closed_gap, penetration});
}

ExactContactResiduals check_exact_contact(const ExactContact& exact, const std::function<double(double)>& gap,
                                          double L, double H1, double H2) {
  ExactContactResiduals r;
  const std::vector<Sample> samples = body_samples(L, H1, H2);
  // each body measured against its own sizes: a stiff body's small displacements count as much
  double u_max[2] = {0, 0}, grad_max[2] = {0, 0}, stress_max[2] = {0, 0};
  for (const Sample& s : samples) {
    u_max[s.body] = std::max(u_max[s.body], exact.u(s.body, s.p).norm());
    grad_max[s.body] = std::max(grad_max[s.body], exact.grad_u(s.body, s.p).norm());
    stress_max[s.body] = std::max(stress_max[s.body], exact.stress(s.body, s.p).norm());
  }
  for (const Sample& s : samples) {
    // 2e-4 of the depth, but no shorter than at 2% of the body's height: at smaller depths
    // round-off (1e-16 |u| / step) would grow past the truncation error it saves
    const double step = 2e-4 * std::max(s.depth, 0.02 * (s.body == 0 ? H1 : H2));
    const auto u = [&](const Eigen::Vector2d& q) -> Eigen::Vector2d { return exact.u(s.body, q); };
    const auto sigma = [&](const Eigen::Vector2d& q) -> Eigen::Matrix2d { return exact.stress(s.body, q); };
    Eigen::Matrix2d D;
    for (int j = 0; j < 2; ++j) D.col(j) = derivative(u, s.p, j, step);
    r.gradient = std::max(r.gradient, (D - exact.grad_u(s.body, s.p)).norm() / grad_max[s.body]);
    const Eigen::Matrix2d dx = derivative(sigma, s.p, 0, step), dy = derivative(sigma, s.p, 1, step);
    const Eigen::Vector2d div(dx(0, 0) + dy(0, 1), dx(1, 0) + dy(1, 1));
    r.equilibrium = std::max(r.equilibrium, (div + exact.body_force(s.body, s.p)).norm() * s.depth / stress_max[s.body]);
  }
  // u on Gamma_c (both components; Dirichlet data at the corners (0, 0) and (L, 0)) is the limit
  // of u from inside each body: u(x, 0) against the quadratic through u(x, +-k delta), k = 1..3
  for (int l = 0; l < 2; ++l) {
    const double delta = 1e-5 * (l == 0 ? H1 : H2), sign = l == 0 ? 1 : -1;
    for (int i = 0; i <= 40; ++i) {
      const double x = L * i / 40.0;
      const auto at = [&](int k) -> Eigen::Vector2d { return exact.u(l, {x, sign * k * delta}); };
      const Eigen::Vector2d limit = 3.0 * (at(1) - at(2)) + at(3);
      r.boundary = std::max(r.boundary, (exact.u(l, {x, 0.0}) - limit).norm() / u_max[l]);
    }
  }

  // Gamma_c: 2001 points, so that both sides of every edge of a contact zone are sampled
  std::vector<double> xs;
  double p_max = 0, u_scale = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double x = L * i / 2000.0;
    xs.push_back(x);
    p_max = std::max(p_max, exact.pressure(x));
    u_scale = std::max({u_scale, std::fabs(gap(x)), std::fabs(exact.u(0, {x, 0.0}).y()),
                        std::fabs(exact.u(1, {x, 0.0}).y())});
  }
  if (!(p_max > 0)) p_max = 1;  // nothing presses: compare with an absolute scale
  if (!(u_scale > 0)) u_scale = 1;
  for (double x : xs) {
    const double p = exact.pressure(x);
    for (int l = 0; l < 2; ++l) {
      const Eigen::Matrix2d sigma = exact.stress(l, {x, 0.0});
      r.traction = std::max({r.traction, std::fabs(sigma(1, 1) + p) / p_max,
                             std::fabs(sigma(0, 1) - exact.shear(x)) / p_max});
    }
    r.sign = std::max(r.sign, std::max(0.0, -p) / p_max);
    const double excess = exact.normal_jump(x) - gap(x);
    if (p > 0) r.closed_gap = std::max(r.closed_gap, std::fabs(excess) / u_scale);
    else r.penetration = std::max(r.penetration, std::max(0.0, excess) / u_scale);
  }
  return r;
}

}  // namespace mortar
