#include "scenes.hpp"

#include <stdexcept>

namespace chapter05 {


UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ManufacturedContact& exact) {
  UnilateralScene u;
  if (s.name == "hertz") {
    u.data = mortar::pressed_between_plates(bodies, s.delta);
    const double x0 = s.L / 2, R = s.R;
    u.gap = [x0, R](double x) { return (x - x0) * (x - x0) / (2 * R); };
  } else if (s.name == "partial") {
    u.data = mortar::pressed_between_plates(bodies, s.delta);
    const double slope = 2 * s.delta / s.L;
    u.gap = [slope](double x) { return slope * x; };
  } else if (s.name == "bilateral") {
    u.data = mortar::manufactured_scene(bodies, exact);
    u.gap = [](double) { return 0.0; };
  } else {
    throw std::invalid_argument("unknown scene '" + s.name + "' (hertz, partial or bilateral)");
  }
  return u;
}

}  // namespace chapter05
