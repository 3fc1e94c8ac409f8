#include "common/manufactured_contact.hpp"

#include <cmath>

namespace mortar {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double A = 0.01;      // amplitude: displacements of about 1% of L
constexpr double s0 = 1.5;      // w = s0 + cos(kx) >= 0.5: pressure of one sign
constexpr double gamma_c = 0.5;  // normal displacement c(x) = gamma sin(kx) / k
}  // namespace

ManufacturedContact::ManufacturedContact(const Material& body1, const Material& body2, double L)
    : m1_(body1), m2_(body2), k_(1.5 * pi / L) {
  alpha_[0] = 1.0;
  alpha_[1] = -0.5;  // different tangential displacements: the interface slips
  beta_[0] = -1.0;
  // (4): lambda_1 alpha_1 + (lambda_1 + 2 mu_1) beta_1 = lambda_2 alpha_2 + (lambda_2 + 2 mu_2) beta_2
  const double S = m1_.lambda() * alpha_[0] + (m1_.lambda() + 2 * m1_.mu()) * beta_[0];
  beta_[1] = (S - m2_.lambda() * alpha_[1]) / (m2_.lambda() + 2 * m2_.mu());
}

Eigen::Vector2d ManufacturedContact::u(int l, const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y();
  const double v = s0 * x + std::sin(k_ * x) / k_, w = s0 + std::cos(k_ * x);
  const double c = gamma_c * std::sin(k_ * x) / k_, dc = gamma_c * std::cos(k_ * x);
  return A * Eigen::Vector2d(alpha_[l] * std::cos(y) * v - y * dc, beta_[l] * std::sin(y) * w + c);
}

Eigen::Matrix2d ManufacturedContact::grad_u(int l, const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y();
  const double v = s0 * x + std::sin(k_ * x) / k_, w = s0 + std::cos(k_ * x);
  const double dw = -k_ * std::sin(k_ * x);
  const double dc = gamma_c * std::cos(k_ * x), ddc = -gamma_c * k_ * std::sin(k_ * x);
  const double a = alpha_[l], b = beta_[l];
  Eigen::Matrix2d G;
  G << a * std::cos(y) * w - y * ddc, -a * std::sin(y) * v - dc,
       b * std::sin(y) * dw + dc, b * std::cos(y) * w;
  return A * G;
}

Eigen::Matrix2d ManufacturedContact::stress(int l, const Eigen::Vector2d& p) const {
  const Eigen::Matrix2d G = grad_u(l, p);
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  const Material& m = material(l);
  return m.lambda() * eps.trace() * Eigen::Matrix2d::Identity() + 2 * m.mu() * eps;
}

Eigen::Vector2d ManufacturedContact::body_force(int l, const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y(), k = k_;
  const double v = s0 * x + std::sin(k * x) / k, w = s0 + std::cos(k * x);
  const double dw = -k * std::sin(k * x), ddw = -k * k * std::cos(k * x);
  const double ddc = -gamma_c * k * std::sin(k * x), dddc = -gamma_c * k * k * std::cos(k * x);
  const double a = alpha_[l], b = beta_[l], cy = std::cos(y), sy = std::sin(y);
  // second derivatives of u_x and u_y (v' = w)
  const double ux_xx = a * cy * dw - y * dddc, ux_xy = -a * sy * w - ddc, ux_yy = -a * cy * v;
  const double uy_xx = b * sy * ddw + ddc, uy_xy = b * cy * dw, uy_yy = -b * sy * w;
  const Material& m = material(l);
  const Eigen::Vector2d laplacian(ux_xx + ux_yy, uy_xx + uy_yy);
  const Eigen::Vector2d grad_div(ux_xx + uy_xy, ux_xy + uy_yy);
  return -A * (m.mu() * laplacian + (m.lambda() + m.mu()) * grad_div);
}

double ManufacturedContact::pressure(double x) const {
  const double S = m1_.lambda() * alpha_[0] + (m1_.lambda() + 2 * m1_.mu()) * beta_[0];
  return -A * S * (s0 + std::cos(k_ * x));
}

double ManufacturedContact::normal_displacement(double x) const {
  return A * gamma_c * std::sin(k_ * x) / k_;
}

ExactSolution ManufacturedContact::exact(int l) const {
  return {[this, l](const Eigen::Vector2d& p) { return u(l, p); },
          [this, l](const Eigen::Vector2d& p) { return grad_u(l, p); }};
}

}  // namespace mortar
