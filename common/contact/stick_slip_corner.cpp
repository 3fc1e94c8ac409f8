#include "common/contact/stick_slip_corner.hpp"

#include <cmath>
#include <complex>

namespace mortar {

namespace {
using Complex = std::complex<double>;

// zeta^{k/2} and its first three derivatives' factors, for the half-plane y >= 0 (y + 0.0:
// on the cut the limit from above)
Complex power(const Complex& zeta, double e) { return std::pow(zeta, e); }

// value, d/dx, d/dy and the Hessian of Re or Im of c zeta^e (e = 3/2, 1/2), y >= 0, from
// d/dx F = F', d/dy F = i F'
struct Jet2 {
  double f = 0, fx = 0, fy = 0, fxx = 0, fxy = 0, fyy = 0;
};
Jet2 harmonic(const Complex& zeta, double e, bool imaginary) {
  const Complex d0 = power(zeta, e), d1 = e * power(zeta, e - 1), d2 = e * (e - 1) * power(zeta, e - 2);
  const auto part = [imaginary](const Complex& z) { return imaginary ? z.imag() : z.real(); };
  const Complex i(0.0, 1.0);
  return {part(d0), part(d1), part(i * d1), part(d2), part(i * d2), -part(d2)};
}
}  // namespace

StickSlipCorner::StickSlipCorner(const Material& body1, const Material& body2, double xc, double C, double K)
    : m1_(body1), m2_(body2), xc_(xc), C_(C), K_(K) {
  D_ = K / body2.mu();
  E_ = -1.5 * C * body1.lambda() / (body1.lambda() + 2 * body1.mu());
  G_ = 1.5 * C - K / body1.mu();
}

StickSlipCorner::Local StickSlipCorner::local(int l, const Eigen::Vector2d& p) const {
  Local r;
  r.hessian[0].setZero();
  r.hessian[1].setZero();
  const double X = p.x() - xc_;
  if (l == 0) {
    const double y = std::fabs(p.y());
    const Complex zeta(X, y + 0.0);
    const bool at_point = X == 0 && y == 0;
    const Jet2 g = at_point ? Jet2{} : harmonic(zeta, 1.5, false);  // Re zeta^{3/2}
    const Jet2 n = at_point ? Jet2{} : harmonic(zeta, 0.5, false);  // Re zeta^{1/2}
    const Jet2 m = at_point ? Jet2{} : harmonic(zeta, 0.5, true);   // Im zeta^{1/2}
    // u_x = C g + G y m; u_y = E y n
    r.u = Eigen::Vector2d(C_ * g.f + G_ * y * m.f, E_ * y * n.f);
    r.grad << C_ * g.fx + G_ * y * m.fx, C_ * g.fy + G_ * (m.f + y * m.fy), E_ * y * n.fx, E_ * (n.f + y * n.fy);
    const double mxy = m.fx + y * m.fxy;  // d2 (y m) / dx dy
    r.hessian[0] << C_ * g.fxx + G_ * y * m.fxx, C_ * g.fxy + G_ * mxy, C_ * g.fxy + G_ * mxy,
                    C_ * g.fyy + G_ * (2 * m.fy + y * m.fyy);
    r.hessian[1] << E_ * y * n.fxx, E_ * (n.fx + y * n.fxy), E_ * (n.fx + y * n.fxy), E_ * (2 * n.fy + y * n.fyy);
    return r;
  }
  // body 2 in y' = -y >= 0: u_x = -D y' ... written as -D y Im zeta'^{1/2} = D y' m, m = Im zeta'^{1/2}
  const double yp = std::fabs(p.y());
  const Complex zeta(X, yp + 0.0);
  const Jet2 m = X == 0 && yp == 0 ? Jet2{} : harmonic(zeta, 0.5, true);
  // w = y' m and its derivatives in (x, y'), then d/dy = -d/dy'
  const double w = yp * m.f, wx = yp * m.fx, wyp = m.f + yp * m.fy;
  const double wxx = yp * m.fxx, wxyp = m.fx + yp * m.fxy, wypyp = 2 * m.fy + yp * m.fyy;
  r.u = Eigen::Vector2d(D_ * w, 0.0);
  r.grad << D_ * wx, -D_ * wyp, 0.0, 0.0;
  r.hessian[0] << D_ * wxx, -D_ * wxyp, -D_ * wxyp, D_ * wypyp;
  return r;
}

Eigen::Vector2d StickSlipCorner::u(int l, const Eigen::Vector2d& p) const { return local(l, p).u; }
Eigen::Matrix2d StickSlipCorner::grad_u(int l, const Eigen::Vector2d& p) const { return local(l, p).grad; }

// div sigma = mu Laplace u + (lambda + mu) grad div u
Eigen::Vector2d StickSlipCorner::div_sigma(int l, const Eigen::Vector2d& p) const {
  const Local r = local(l, p);
  const Material& m = l == 0 ? m1_ : m2_;
  const double mu = m.mu(), lm = m.lambda() + m.mu();
  const Eigen::Matrix2d& hx = r.hessian[0];
  const Eigen::Matrix2d& hy = r.hessian[1];
  return {mu * (hx(0, 0) + hx(1, 1)) + lm * (hx(0, 0) + hy(0, 1)),
          mu * (hy(0, 0) + hy(1, 1)) + lm * (hx(0, 1) + hy(1, 1))};
}

double StickSlipCorner::shear(double x) const {
  const double X = x - xc_;
  return X < 0 ? -K_ * std::sqrt(-X) : 0.0;
}

double StickSlipCorner::slip(double x) const {
  const double X = x - xc_;
  return X > 0 ? C_ * X * std::sqrt(X) : 0.0;
}

}  // namespace mortar
