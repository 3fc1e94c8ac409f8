#include "scenes.hpp"

#include <stdexcept>

namespace chapter05 {

mortar::ManufacturedContact make_exact(const SceneParameters& s, const mortar::Material& body1,
                                       const mortar::Material& body2) {
  if (s.name == "signorini")
    return {body1, body2, mortar::signorini_profile(s.L, mortar::signorini_contact_point(s.L))};
  return {body1, body2, s.L};
}

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
  } else if (s.name == "signorini") {
    u.data = mortar::manufactured_scene_all_sides(bodies, exact);
    const double L = s.L;
    u.gap = [L](double x) { return mortar::signorini_gap(L, x); };
  } else {
    throw std::invalid_argument("unknown scene '" + s.name + "' (hertz, partial, bilateral or signorini)");
  }
  return u;
}

}  // namespace chapter05
