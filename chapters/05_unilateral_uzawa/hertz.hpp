// Plane-strain Hertz contact of two elastic half-spaces whose initial gap is x^2 / (2R)
// (Johnson, Contact Mechanics, section 4.3): for a force P per unit length,
//   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,   a = sqrt(4 P R / (pi E*)),
//   p(x) = p0 sqrt(1 - x^2 / a^2),            p0 = 2 P / (pi a).
#pragma once

namespace chapter05 {

struct Hertz {
  double E_star = 0, R = 0, P = 0;
  double half_width() const;
  double peak_pressure() const;
  double pressure(double distance_from_centre) const;
};

Hertz hertz_at_force(double E1, double nu1, double E2, double nu2, double R, double P);

}  // namespace chapter05
