#include "common/contact/cattaneo_half_planes.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include "common/contact/elliptic_edge_load.hpp"

namespace mortar {

namespace {
// (1 - 2 nu) / mu of a material: Dundurs' beta is 0 when both bodies have the same
double dundurs_measure(const Material& m) { return (1 - 2 * m.nu()) / m.mu(); }

// G, G' and G'' (header) of the shear q at X + i z: G' = -(W''_a + W''_c) for the two elliptical
// loads of q, peak F p0 on |X| < a and -F p0 c/a on |X| < c
struct ShearPotential {
  std::complex<double> g0, g1, g2;
};
ShearPotential shear_potential(double X, double z, double a, double c, double Fp0) {
  const EllipticEdgeLoad outer = elliptic_edge_load(X, z, a, Fp0);
  ShearPotential g{-outer.d1, -outer.d2, -outer.d3};
  if (c > 0) {
    const EllipticEdgeLoad inner = elliptic_edge_load(X, z, c, -Fp0 * c / a);
    g.g0 -= inner.d1;
    g.g1 -= inner.d2;
    g.g2 -= inner.d3;
  }
  return g;
}
}  // namespace

CattaneoHalfPlanes::CattaneoHalfPlanes(const Material& body1, const Material& body2, double x0, double a, double R,
                                       double friction, double q_ratio)
    : ExactContact(body1, body2), normal_(body1, body2, x0, a, R), F_(friction) {
  if (!(friction > 0) || !(q_ratio >= 0) || !(q_ratio < 1))
    throw std::invalid_argument("Cattaneo-Mindlin half-planes need F > 0 and 0 <= Q/(F P) < 1 (F = " +
                                std::to_string(friction) + ", Q/(F P) = " + std::to_string(q_ratio) + ")");
  const double d1 = dundurs_measure(body1), d2 = dundurs_measure(body2);
  if (std::fabs(d1 - d2) > 1e-12 * std::max(std::fabs(d1), std::fabs(d2)))
    throw std::invalid_argument("Cattaneo-Mindlin's field solves the two-body problem only when Dundurs' beta is 0, "
                                "(1 - 2 nu1)/mu1 = (1 - 2 nu2)/mu2 (one material, say)");
  c_ = a * std::sqrt(1 - q_ratio);
  for (int l = 0; l < 2; ++l) {
    rigid_[l] = Eigen::Vector2d::Zero();
    rigid_[l] = u(l, Eigen::Vector2d(x0, 0.0)) - normal_.u(l, Eigen::Vector2d(x0, 0.0));
  }
}

Eigen::Vector2d CattaneoHalfPlanes::shear_displacement(int l, double X, double z) const {
  const double a = normal_.half_width();
  const ShearPotential g = shear_potential(X, z, a, c_, F_ * normal_.peak_pressure());
  const double nu = material(l).nu(), two_mu = 2 * material(l).mu();
  return Eigen::Vector2d(2 * (1 - nu) * g.g0.imag() + z * g.g1.real(),
                         -(1 - 2 * nu) * g.g0.real() - z * g.g1.imag()) / two_mu;
}

Eigen::Matrix2d CattaneoHalfPlanes::shear_gradient(int l, double X, double z) const {
  const double a = normal_.half_width();
  const ShearPotential g = shear_potential(X, z, a, c_, F_ * normal_.peak_pressure());
  const double nu = material(l).nu(), two_mu = 2 * material(l).mu();
  // d/dX of F(zeta) is F', d/dz is i F'
  Eigen::Matrix2d G;
  G << 2 * (1 - nu) * g.g1.imag() + z * g.g2.real(), (3 - 2 * nu) * g.g1.real() - z * g.g2.imag(),
       -(1 - 2 * nu) * g.g1.real() - z * g.g2.imag(), -2 * nu * g.g1.imag() - z * g.g2.real();
  return G / two_mu;
}

// Body 1 is the half-plane under +q (z = y); body 2 the mirror image of one under -q (z = -y,
// u_y = -U_z): U of body 2 is minus the field of +q.
Eigen::Vector2d CattaneoHalfPlanes::u(int l, const Eigen::Vector2d& p) const {
  const double X = p.x() - normal_.centre(), z = std::fabs(p.y());
  Eigen::Vector2d U = shear_displacement(l, X, z);
  if (l == 1) U = Eigen::Vector2d(-U.x(), U.y());  // -U, then u_y = -U_z
  return normal_.u(l, p) + U - rigid_[l];
}

Eigen::Matrix2d CattaneoHalfPlanes::grad_u(int l, const Eigen::Vector2d& p) const {
  const double X = p.x() - normal_.centre(), z = std::fabs(p.y());
  Eigen::Matrix2d G = shear_gradient(l, X, z);
  if (l == 1) {  // -grad U, then d/dy = -d/dz and u_y = -U_z
    G = -G;
    G(0, 1) = -G(0, 1);
    G(1, 0) = -G(1, 0);
  }
  return normal_.grad_u(l, p) + G;
}

double CattaneoHalfPlanes::shear(double x) const {
  const double X = x - normal_.centre(), a = normal_.half_width(), Fp0 = F_ * normal_.peak_pressure();
  const auto ellipse = [X](double b) { return std::fabs(X) < b ? std::sqrt(1 - (X / b) * (X / b)) : 0.0; };
  return Fp0 * (ellipse(a) - (c_ > 0 ? c_ / a * ellipse(c_) : 0.0));
}

double CattaneoHalfPlanes::slip(double x) const {
  const Eigen::Vector2d on_gamma(x, 0.0);
  return u(0, on_gamma).x() - u(1, on_gamma).x();
}

double CattaneoHalfPlanes::shear_force() const {
  const double a = normal_.half_width();
  return F_ * normal_.total_force(0.0) * (1 - c_ * c_ / (a * a));
}

}  // namespace mortar
