#include "common/contact/hertz_half_planes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/contact/elliptic_edge_load.hpp"

namespace mortar {

namespace {
constexpr double pi = 3.14159265358979323846;
}  // namespace

HertzHalfPlanes::HertzHalfPlanes(const Material& body1, const Material& body2, double x0, double a, double R)
    : ExactContact(body1, body2), x0_(x0), a_(a), R_(R) {
  if (!(a > 0) || !(R > 0))
    throw std::invalid_argument("Hertz half-planes need a > 0 and R > 0 (a = " + std::to_string(a) +
                                ", R = " + std::to_string(R) + ")");
  e_star_ = 1.0 / ((1 - body1.nu() * body1.nu()) / body1.E() + (1 - body2.nu() * body2.nu()) / body2.E());
  p0_ = a * e_star_ / (2 * R);  // the edge displacements close the parabola X^2 / (2R)
  for (int l = 0; l < 2; ++l) {
    rigid_[l] = Eigen::Vector2d::Zero();
    rigid_[l] = u(l, Eigen::Vector2d(x0, 0.0));
  }
}

Eigen::Vector2d HertzHalfPlanes::half_plane_displacement(int l, double X, double z) const {
  const EllipticEdgeLoad f = elliptic_edge_load(X, z, a_, p0_);  // Phi', Phi'', Phi'''
  const double nu = material(l).nu(), two_mu = 2 * material(l).mu();
  const double phi_x = f.d1.real(), phi_z = -f.d1.imag();
  const double phi_xz = -f.d2.imag(), phi_zz = -f.d2.real();
  return Eigen::Vector2d((1 - 2 * nu) * phi_x + z * phi_xz, -2 * (1 - nu) * phi_z + z * phi_zz) / two_mu;
}

Eigen::Matrix2d HertzHalfPlanes::half_plane_gradient(int l, double X, double z) const {
  const EllipticEdgeLoad f = elliptic_edge_load(X, z, a_, p0_);  // Phi', Phi'', Phi'''
  const double nu = material(l).nu(), two_mu = 2 * material(l).mu();
  const double phi_xx = f.d2.real(), phi_xz = -f.d2.imag(), phi_zz = -f.d2.real();
  const double phi_xxz = -f.d3.imag(), phi_xzz = -f.d3.real(), phi_zzz = f.d3.imag();
  Eigen::Matrix2d G;
  G << (1 - 2 * nu) * phi_xx + z * phi_xxz, 2 * (1 - nu) * phi_xz + z * phi_xzz,
       -2 * (1 - nu) * phi_xz + z * phi_xzz, -(1 - 2 * nu) * phi_zz + z * phi_zzz;
  return G / two_mu;
}

// Body 1 is the half-plane itself (z = y); body 2 its mirror image (z = -y, u_y = -U_z).
Eigen::Vector2d HertzHalfPlanes::u(int l, const Eigen::Vector2d& p) const {
  const double X = p.x() - x0_, z = std::fabs(p.y());
  Eigen::Vector2d U = half_plane_displacement(l, X, z);
  if (l == 1) U.y() = -U.y();
  return U - rigid_[l];
}

Eigen::Matrix2d HertzHalfPlanes::grad_u(int l, const Eigen::Vector2d& p) const {
  const double X = p.x() - x0_, z = std::fabs(p.y());
  Eigen::Matrix2d G = half_plane_gradient(l, X, z);
  if (l == 1) {  // d/dy = -d/dz, and u_y = -U_z
    G(0, 1) = -G(0, 1);
    G(1, 0) = -G(1, 0);
  }
  return G;
}

double HertzHalfPlanes::pressure(double x) const {
  const double s = (x - x0_) / a_;
  return std::fabs(s) < 1 ? p0_ * std::sqrt(1 - s * s) : 0.0;
}

double HertzHalfPlanes::total_force(double) const { return 0.5 * pi * a_ * p0_; }

double HertzHalfPlanes::gap(double x) const { return (x - x0_) * (x - x0_) / (2 * R_); }

double HertzHalfPlanes::open_gap(double x) const {
  const double X = std::fabs(x - x0_), d = X - a_;
  if (d <= 0) return 0.0;
  const double r = d / a_, scale = p0_ / (a_ * e_star_);
  // close to the edge the two terms below cancel: the series of their difference instead,
  // (4/3) sqrt(2a) d^{3/2} (1 + 3r/20 - 3r^2/224), r = d/a, exact to O(r^3)
  if (r < 1e-3) return scale * 4.0 / 3 * std::sqrt(2 * a_) * d * std::sqrt(d) * (1 + 0.15 * r - 3.0 / 224 * r * r);
  const double s = std::sqrt(d * (X + a_));  // sqrt(X^2 - a^2), acosh(X/a) = log1p((d + s)/a)
  return scale * (X * s - a_ * a_ * std::log1p((d + s) / a_));
}

}  // namespace mortar
