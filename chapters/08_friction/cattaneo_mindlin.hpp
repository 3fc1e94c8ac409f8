// Cattaneo (1938) and Mindlin (1949): two elastic half-planes of the same material pressed by a
// normal load P (per unit length), then sheared by Q < F P (Johnson, Contact Mechanics, 7.2).
// With identical materials (Dundurs' beta = 0) the shear does not change the pressure, which
// stays Hertz's, p(x) = p0 sqrt(1 - X^2 / a^2), X = x - x0, plane strain:
//
//   a = sqrt(4 R P / (pi E*)),  p0 = 2 P / (pi a),
//
// and the shear is Coulomb's limit F p minus the Hertz-shaped traction of a smaller zone,
//
//   q(X) = F p0 (sqrt(1 - X^2/a^2) - (c/a) sqrt(1 - X^2/c^2))  on the stick zone |X| < c,
//   q(X) = F p(X)                                              on the slip zone c <= |X| < a,
//
// with c / a = sqrt(1 - Q / (F P)): int q = Q. At Q = F P the stick zone vanishes (gross
// sliding). q has the sign of Q; here lambda_t = q (the shear on Gamma_c).
#pragma once

namespace chapter08 {

class CattaneoMindlin {
 public:
  // Q in [0, F P]; e_star from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
  CattaneoMindlin(double P, double Q, double friction, double e_star, double R, double x0);
  double pressure(double x) const;
  double shear(double x) const;
  double half_width() const { return a_; }
  double stick_half_width() const { return c_; }
  double peak_pressure() const { return p0_; }

 private:
  double x0_, a_, p0_, F_, c_;
};

}  // namespace chapter08
