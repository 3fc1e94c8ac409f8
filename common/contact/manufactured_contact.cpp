#include "common/contact/manufactured_contact.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mortar {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double A = 0.01;       // amplitude: displacements of about 1% of L
constexpr double s0 = 1.5;       // w = s0 + cos(kx) >= 0.5: pressure of one sign
constexpr double gamma_c = 0.5;  // normal displacement c(x) = gamma sin(kx) / k

// c(x) = gamma sin(k x) / k and its derivatives, k = 1.5 pi / L: every profile's normal
// displacement on Gamma_c.
void add_normal_displacement(ProfileValues& p, double x, double L) {
  const double k = 1.5 * pi / L, s = std::sin(k * x), co = std::cos(k * x);
  p.c = gamma_c * s / k;
  p.dc = gamma_c * co;
  p.ddc = -gamma_c * k * s;
  p.dddc = -gamma_c * k * k * co;
}

// w = s0 + cos(k x), v = s0 x + sin(k x) / k.
ContactProfile cosine_profile(double L, double k) {
  return [L, k](double x) {
    ProfileValues p;
    p.v = s0 * x + std::sin(k * x) / k;
    p.w = s0 + std::cos(k * x);
    p.dw = -k * std::sin(k * x);
    p.ddw = -k * k * std::cos(k * x);
    add_normal_displacement(p, x, L);
    return p;
  };
}
}  // namespace

ContactProfile sloped_profile(double L) { return cosine_profile(L, 1.5 * pi / L); }
ContactProfile flat_ends_profile(double L) { return cosine_profile(L, 2 * pi / L); }

double signorini_contact_point(double L) { return L * (0.5 + std::sqrt(2.0) / 10); }

double signorini_gap(double L, double x) {
  const double open = std::max(0.0, x - signorini_contact_point(L));
  return A * open * open / L;
}

ContactProfile signorini_profile(double L, double x_star) {
  // w = 4 s^3 with s = (x* - x)_+ / L: C^2 across x*, so u is in H^{7/2 - eps} on each body
  // (more than the H^2 of Theorem 5.1) and f = -div sigma, which holds w'', is continuous.
  return [L, x_star](double x) {
    const double s = std::max(0.0, x_star - x) / L;
    ProfileValues p;
    p.v = -L * s * s * s * s;
    p.w = 4 * s * s * s;
    p.dw = -12 * s * s / L;
    p.ddw = 24 * s / (L * L);
    add_normal_displacement(p, x, L);
    return p;
  };
}

ManufacturedContact::ManufacturedContact(const Material& body1, const Material& body2, double L)
    : ManufacturedContact(body1, body2, sloped_profile(L), L) {}

ManufacturedContact::ManufacturedContact(const Material& body1, const Material& body2, ContactProfile profile,
                                         double L)
    : ExactContact(body1, body2), profile_(std::move(profile)), L_(L) {
  alpha_[0] = 1.0;
  alpha_[1] = -0.5;  // different tangential displacements: the interface slips
  beta_[0] = -1.0;
  // (4): lambda_1 alpha_1 + (lambda_1 + 2 mu_1) beta_1 = lambda_2 alpha_2 + (lambda_2 + 2 mu_2) beta_2
  const double S = material(0).lambda() * alpha_[0] + (material(0).lambda() + 2 * material(0).mu()) * beta_[0];
  beta_[1] = (S - material(1).lambda() * alpha_[1]) / (material(1).lambda() + 2 * material(1).mu());
}

Eigen::Vector2d ManufacturedContact::u(int l, const Eigen::Vector2d& p) const {
  const double y = p.y(), Y = y / L_;
  const ProfileValues f = profile_(p.x());
  return A * Eigen::Vector2d(alpha_[l] * std::cos(Y) * f.v - y * f.dc, beta_[l] * L_ * std::sin(Y) * f.w + f.c);
}

Eigen::Matrix2d ManufacturedContact::grad_u(int l, const Eigen::Vector2d& p) const {
  const double y = p.y(), Y = y / L_;
  const ProfileValues f = profile_(p.x());
  const double a = alpha_[l], b = beta_[l];
  Eigen::Matrix2d G;
  G << a * std::cos(Y) * f.w - y * f.ddc, -a * std::sin(Y) * f.v / L_ - f.dc,
       b * L_ * std::sin(Y) * f.dw + f.dc, b * std::cos(Y) * f.w;
  return A * G;
}

Eigen::Vector2d ManufacturedContact::body_force(int l, const Eigen::Vector2d& p) const {
  const double y = p.y(), Y = y / L_;
  const ProfileValues f = profile_(p.x());
  const double a = alpha_[l], b = beta_[l], cy = std::cos(Y), sy = std::sin(Y);
  // second derivatives of u_x and u_y (v' = w)
  const double ux_xx = a * cy * f.dw - y * f.dddc, ux_xy = -a * sy * f.w / L_ - f.ddc,
               ux_yy = -a * cy * f.v / (L_ * L_);
  const double uy_xx = b * L_ * sy * f.ddw + f.ddc, uy_xy = b * cy * f.dw, uy_yy = -b * sy * f.w / L_;
  const Material& m = material(l);
  const Eigen::Vector2d laplacian(ux_xx + ux_yy, uy_xx + uy_yy);
  const Eigen::Vector2d grad_div(ux_xx + uy_xy, ux_xy + uy_yy);
  return -A * (m.mu() * laplacian + (m.lambda() + m.mu()) * grad_div);
}

double ManufacturedContact::pressure(double x) const {
  const double S = material(0).lambda() * alpha_[0] + (material(0).lambda() + 2 * material(0).mu()) * beta_[0];
  return -A * S * profile_(x).w;
}

double ManufacturedContact::normal_displacement(double x) const { return A * profile_(x).c; }

}  // namespace mortar
