#include "common/contact/manufactured_friction.hpp"

#include <cmath>

namespace mortar {

namespace {
constexpr double pi = 3.14159265358979323846;
using Jet = ManufacturedFriction::Jet;

// a sin(pi x / L) and a cos(pi x / L) with their derivatives
Jet sine(double a, double x, double L) {
  const double k = pi / L, s = std::sin(k * x), c = std::cos(k * x);
  return {a * s, a * k * c, -a * k * k * s, -a * k * k * k * c};
}
Jet cosine(double a, double x, double L) {
  const double k = pi / L, s = std::sin(k * x), c = std::cos(k * x);
  return {a * c, -a * k * s, -a * k * k * c, a * k * k * k * s};
}
Jet operator+(Jet a, const Jet& b) { return {a.f + b.f, a.d1 + b.d1, a.d2 + b.d2, a.d3 + b.d3}; }
Jet operator*(double s, Jet a) { return {s * a.f, s * a.d1, s * a.d2, s * a.d3}; }

double e_star(const Material& a, const Material& b) {
  return 1.0 / ((1 - a.nu() * a.nu()) / a.E() + (1 - b.nu() * b.nu()) / b.E());
}
}  // namespace

namespace {
double stick_slip_point_of(double L) { return L * (0.4 + std::sqrt(2.0) / 100); }
}  // namespace

// K sqrt(x_c) = 1.5 F S: the shear at x = 0 is F S - 1.5 F S = -F S / 2; C = 2 eps / sqrt(L):
// the slip 2 eps L ((x - x_c) / L)^{3/2}, friction or not (header)
ManufacturedFriction::ManufacturedFriction(const Material& body1, const Material& body2, double L, double friction)
    : ExactContact(body1, body2),
      L_(L),
      F_(friction),
      xc_(stick_slip_point_of(L)),
      eps_(1e-3),
      S_(1e-3 * e_star(body1, body2)),
      corner_(body1, body2, xc_, 2 * eps_ / std::sqrt(L), 1.5 * friction * S_ / std::sqrt(xc_)) {}

Jet ManufacturedFriction::pressure_jet(double x) const { return Jet{S_, 0, 0, 0} + sine(0.3 * S_, x, L_); }

Jet ManufacturedFriction::shear_jet(double x) const { return F_ * pressure_jet(x); }

double ManufacturedFriction::pressure(double x) const { return pressure_jet(x).f; }
double ManufacturedFriction::shear(double x) const { return shear_jet(x).f + corner_.shear(x); }
double ManufacturedFriction::slip(double x) const { return corner_.slip(x); }
double ManufacturedFriction::threshold(double x) const { return F_ * pressure(x); }

ManufacturedFriction::Profiles ManufacturedFriction::profiles(int l, double x) const {
  const Material& m = material(l);
  const double lambda = m.lambda(), mu = m.mu();
  Profiles q;
  q.c = cosine(0.5 * L_ * eps_, x, L_);
  q.A = sine(0.3 * L_ * eps_, x, L_);
  // sigma_12 = mu (P + c') = F p on y = 0 (the corner adds the rest of tau)
  const Jet tau = shear_jet(x), p = pressure_jet(x);
  q.P = {tau.f / mu - q.c.d1, tau.d1 / mu - q.c.d2, tau.d2 / mu - q.c.d3, 0};
  // sigma_22 = lambda A' + (lambda + 2 mu) Q = -p on y = 0
  const double k = -1.0 / (lambda + 2 * mu);
  q.Q = {k * (p.f + lambda * q.A.d1), k * (p.d1 + lambda * q.A.d2), k * (p.d2 + lambda * q.A.d3), 0};
  q.R = cosine((l == 0 ? 0.4 : -0.3) * eps_ / L_, x, L_);
  q.T = sine((l == 0 ? 0.2 : 0.25) * eps_ / L_, x, L_);
  return q;
}

Eigen::Vector2d ManufacturedFriction::u(int l, const Eigen::Vector2d& p) const {
  const Profiles q = profiles(l, p.x());
  const double y = p.y();
  return Eigen::Vector2d(q.A.f + y * q.P.f + y * y * q.R.f, q.c.f + y * q.Q.f + y * y * q.T.f) + corner_.u(l, p);
}

Eigen::Matrix2d ManufacturedFriction::grad_u(int l, const Eigen::Vector2d& p) const {
  const Profiles q = profiles(l, p.x());
  const double y = p.y();
  Eigen::Matrix2d g;
  g << q.A.d1 + y * q.P.d1 + y * y * q.R.d1, q.P.f + 2 * y * q.R.f,
       q.c.d1 + y * q.Q.d1 + y * y * q.T.d1, q.Q.f + 2 * y * q.T.f;
  return g + corner_.grad_u(l, p);
}

Eigen::Vector2d ManufacturedFriction::body_force(int l, const Eigen::Vector2d& p) const {
  const Profiles q = profiles(l, p.x());
  const Material& m = material(l);
  const double lambda = m.lambda(), mu = m.mu(), y = p.y();
  // d sigma_11 / dx + d sigma_12 / dy and d sigma_12 / dx + d sigma_22 / dy
  const double div_x = (lambda + 2 * mu) * (q.A.d2 + y * q.P.d2 + y * y * q.R.d2) + lambda * (q.Q.d1 + 2 * y * q.T.d1) +
                       mu * (2 * q.R.f + q.Q.d1 + 2 * y * q.T.d1);
  const double div_y = mu * (q.P.d1 + 2 * y * q.R.d1 + q.c.d2 + y * q.Q.d2 + y * y * q.T.d2) +
                       lambda * (q.P.d1 + 2 * y * q.R.d1) + (lambda + 2 * mu) * 2 * q.T.f;
  return Eigen::Vector2d(-div_x, -div_y) - corner_.div_sigma(l, p);
}

}  // namespace mortar
